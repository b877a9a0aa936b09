"""Execute lessons with nbclient: real outputs, or an error that says where.

Each execution gets a fresh kernel of the project's interpreter, its own ROS
domain (isolation.py) and a scratch working folder shaped like a student's
workspace after its first ``colcon build`` (``src/`` with a copy of each book
package, ``install/`` a copy of the book's built install, sourced).  When
the kernel is gone, processes the lesson left running are stopped and the
lesson fails: lessons must clean up after themselves.
"""
from __future__ import annotations

import copy
import multiprocessing
import os
import shutil
import tempfile
import uuid
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import nbformat
from jupyter_client.kernelspec import KernelSpecManager
from jupyter_client.manager import AsyncKernelManager
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError, CellTimeoutError, DeadKernelError
from traitlets import default

from . import cache, paths, reaper, settings, workspace
from .environment import ros_env
from .isolation import DomainLease, acquire_domain, holding_fixed_domains
from .lessons import Lesson, load

#: labkit.exercises reads it (kept in step with labkit.exercises.APPLY_SOLUTIONS).
APPLY_SOLUTIONS = 'TEXTBOOK_APPLY_SOLUTIONS'


class NativeKernelManager(AsyncKernelManager):
    """Always the native kernel of this interpreter (the project's .venv), never a
    "python3" kernel that some other tool registered for the user."""

    @default('transport')
    def _transport_default(self) -> str:
        return 'ipc'  # unix sockets: the kernel is reachable from this machine only

    @default('ip')
    def _ip_default(self) -> str:
        # An absolute socket path: the kernel runs in another working directory.
        return os.path.join(tempfile.gettempdir(), f'textbook-kernel-{uuid.uuid4().hex[:12]}')

    @default('kernel_spec_manager')
    def _kernel_spec_manager_default(self) -> KernelSpecManager:
        return KernelSpecManager(kernel_dirs=[])


class LessonExecutionError(RuntimeError):
    """A cell of a lesson failed, timed out, or the lesson left processes behind."""


def _cell_line(lesson: Lesson, cell: nbformat.NotebookNode) -> int | None:
    """1-based line of the lesson file where ``cell`` starts (best effort)."""
    first = next((line for line in cell.source.splitlines() if line.strip()), None)
    if first is None:
        return None
    for number, line in enumerate(lesson.text.splitlines(), start=1):
        if line.strip() == first.strip():
            return number
    return None


def _output_tail(cell: nbformat.NotebookNode, lines: int = 15) -> str:
    text = ''.join(out.get('text', '') for out in cell.get('outputs', [])
                   if out.get('output_type') == 'stream')
    tail = text.rstrip().splitlines()[-lines:]
    return '\n'.join('    | ' + line for line in tail)


def _failure(lesson: Lesson, notebook: nbformat.NotebookNode, index: int | None,
             error: str) -> LessonExecutionError:
    if index is None:
        return LessonExecutionError(f'{lesson.source}: {error}')
    cell = notebook.cells[index]
    line = _cell_line(lesson, cell)
    where = f'{lesson.source}:{line}' if line else lesson.source
    first = cell.source.strip().splitlines()[0] if cell.source.strip() else ''
    message = f'{where}: cell {index + 1} ({first!r}) failed: {error}'
    tail = _output_tail(cell)
    return LessonExecutionError(message + ('\n  output before the error:\n' + tail if tail else ''))


def _workdir(lesson: Lesson, token: str) -> Path:
    return student_workspace(paths.RUNS / f'{lesson.path.stem}-{token}',
                             built=not lesson.meta.get('builds_workspace', False))


def student_workspace(folder: Path, built: bool = True) -> Path:
    """Create ``folder`` like ``~/ros2_ws`` after the student's first ``colcon
    build``: ``src/`` holds a copy of every book package of ``snippets/`` and
    room for the student's own package, ``install/`` a copy of what the book's
    build installed from them (so ``colcon build --packages-select`` of one
    package finds the others built in this workspace, as on a student's
    machine, and does not warn that they "haven't been built").  Without
    ``built``, ``install/`` is left for the lesson's own first build.

    Copies, not links: a lesson that edits, ``cp -r`` or ``sed -i``s a file in
    ``src/`` must never change ``snippets/``, and ``ls``/``find`` show plain
    folders, as in a student's workspace.  Shared by the book's build and the
    lab kernel (lab_kernel.py), so both run a lesson in the same place.
    """
    (folder / 'src').mkdir(parents=True)
    for package in sorted(p.parent for p in paths.SNIPPETS.glob('*/package.xml')):
        shutil.copytree(package, folder / 'src' / package.name,
                        ignore=shutil.ignore_patterns('__pycache__'))
    if built:
        # Without the bytecode earlier runs left in the book's install/ (`ros2 launch`
        # writes __pycache__/ next to a launch file): what a lesson lists is what its
        # own runs made, whichever tests used the book's build before.
        shutil.copytree(workspace.ensure_built().resolve(), folder / 'install', symlinks=True,
                        ignore=shutil.ignore_patterns('__pycache__'))
    return folder


def student_env(lease: DomainLease, folder: Path) -> dict[str, str]:
    """The environment of a kernel in ``folder`` (a :func:`student_workspace`):
    ``lease``'s domain and the folder's own ``install/setup.bash`` sourced (the
    book's, while the lesson has not built the folder yet)."""
    install = folder / 'install'
    if not install.is_dir():
        return ros_env(lease)
    return workspace.sourced_env(ros_env(lease, source_workspace=False), install)


def execute(lesson: Lesson, timeout: int | None = None) -> nbformat.NotebookNode:
    """Run every cell of ``lesson`` in a new kernel; returns the executed notebook.

    ``timeout``: seconds a cell may run (default: the ``cell_timeout`` setting).
    """
    timeout = settings.load().cell_timeout if timeout is None else timeout
    notebook = copy.deepcopy(lesson.notebook)
    with acquire_domain() as lease, holding_fixed_domains(lesson.meta.get('fixed_domains', ())):
        workdir = _workdir(lesson, lease.token)
        env = student_env(lease, workdir)
        # The book's build shows every solution passing its check: solution
        # cells apply the solution and a failing check fails the lesson.
        env[APPLY_SOLUTIONS] = '1'
        current: dict[str, int | None] = {'index': None}
        client = NotebookClient(
            notebook, kernel_manager_class=NativeKernelManager, timeout=timeout,
            kernel_name='python3',
            allow_errors=False, coalesce_streams=True,
            resources={'metadata': {'path': str(workdir)}},
            on_cell_execute=lambda cell, cell_index: current.update(index=cell_index))
        try:
            client.execute(env=env)
        except CellTimeoutError:
            raise _failure(lesson, notebook, current['index'],
                           f'no result after {timeout} s (hung?)') from None
        except CellExecutionError as error:
            raise _failure(lesson, notebook, current['index'],
                           f'{error.ename}: {error.evalue}') from None
        except DeadKernelError as error:
            raise _failure(lesson, notebook, current['index'],
                           f'the kernel died: {error}') from None
        finally:
            leftovers = reaper.reap([lease.token])
            shutil.rmtree(workdir, ignore_errors=True)
        if leftovers:
            raise LessonExecutionError(
                f'{lesson.source}: processes were still running after the last cell '
                f'(stopped them; stop what a lesson starts):\n  ' + '\n  '.join(leftovers))
    return shown_in_home(notebook, workdir)


def shown_in_home(notebook: nbformat.NotebookNode, workdir: Path) -> nbformat.NotebookNode:
    """``notebook`` with the build machine's folders in its outputs written as
    :func:`paths.shown` writes them: the paths a student's terminal shows, not the
    build machine's temporary folder or checkout."""
    def shown(text: str) -> str:
        return paths.shown(text, workdir)

    for cell in notebook.cells:
        for output in cell.get('outputs', []):
            if 'text' in output:
                output['text'] = shown(output['text'])
            for kind, value in output.get('data', {}).items():
                if kind.startswith('text/') and isinstance(value, str):
                    output['data'][kind] = shown(value)
    return notebook


def executed(lesson: Lesson) -> nbformat.NotebookNode:
    """The executed notebook of ``lesson``: from the cache, or by running it."""
    key = cache.lesson_key(lesson)
    with cache.exclusive(key):
        hit = cache.cached(key)
        if hit is not None:
            return cache.merge_outputs(lesson, hit)
        notebook = execute(lesson)
        cache.store(key, notebook)
        return notebook


def refresh(lesson: Lesson) -> nbformat.NotebookNode:
    """Execute ``lesson`` even if cached, and store the result."""
    key = cache.lesson_key(lesson)
    with cache.exclusive(key):
        notebook = execute(lesson)
        cache.store(key, notebook)
        return notebook


def publish(lesson: Lesson) -> Path:
    """Execute (or fetch) ``lesson`` and place it under build/notebooks for the site."""
    return cache.write_atomic(executed(lesson), paths.NOTEBOOKS / lesson.site_path)


def _publish_path(path: str) -> str:
    return str(publish(load(Path(path))))


def publish_all(lessons: list[Lesson], jobs: int | None = None) -> dict[str, Path]:
    """Publish every lesson, ``jobs`` at a time (default: the ``jobs`` setting);
    raises one error listing all failures."""
    jobs = settings.load().jobs if jobs is None else jobs
    results: dict[str, Path] = {}
    failures: list[str] = []
    stale = [lesson for lesson in lessons if cache.cached(cache.lesson_key(lesson)) is None]
    for lesson in lessons:
        if all(lesson is not other for other in stale):
            results[lesson.source] = publish(lesson)
    if len(stale) == 1 or jobs <= 1:
        for lesson in stale:
            try:
                results[lesson.source] = publish(lesson)
            except LessonExecutionError as error:
                failures.append(str(error))
    elif stale:
        # "spawn": the caller may be a threaded server; forking it is unsafe.
        context = multiprocessing.get_context('spawn')
        with ProcessPoolExecutor(max_workers=jobs, mp_context=context) as pool:
            futures = {lesson.source: pool.submit(_publish_path, str(lesson.path))
                       for lesson in stale}
            for source, future in futures.items():
                try:
                    results[source] = Path(future.result())
                except LessonExecutionError as error:
                    failures.append(str(error))
    if failures:
        raise LessonExecutionError('\n'.join(failures))
    return results
