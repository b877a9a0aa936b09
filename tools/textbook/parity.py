"""`python -m textbook parity`: every lesson on both stacks, compared cell by cell.

The book promises that each output on a page is what a student sees on a real
ROS 2 Jazzy.  The site is built on the headless stack (the clean room); this
command executes the lessons a second time with a real Jazzy sourced (by
default the run-only reference in ../shared/jazzy-reference, installed into
build/jazzy-reference) in an environment of its own (build/jazzy/venv, its
products in build/jazzy), and compares the code cells' outputs after
normalising only what varies from run to run (`parity_compare.normalise`).

Both sides use the lesson cache, so a lesson whose code cells, snippets and
tools did not change is not executed again.  The report goes to
build/parity/report.json and a table to stdout; the exit code is 1 when a
lesson failed on either stack or a cell differs outside the allow-list
(tools/textbook/parity_allowed.yaml, each entry with its reason).  Each
lesson that held is written to the committed parity record
(tools/textbook/parity_record.yaml, see `parity_record`), each that did not
is taken out of it; `--stale` compares only the lessons the record no
longer covers, which is how CI runs it.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from pathlib import Path

import nbformat

from . import parity_record, paths
from .lessons import Lesson, load_all
from .parity_compare import JAZZY_BUILD, LessonParity, compare, load_allowed

JAZZY_VENV = JAZZY_BUILD / 'venv'
REFERENCE_INSTALLER = paths.ROOT.parent / 'shared' / 'jazzy-reference' / 'install.sh'
REFERENCE_PREFIX = paths.ROOT / 'build' / 'jazzy-reference'
REPORT = paths.ROOT / 'build' / 'parity' / 'report.json'


# -- executing -------------------------------------------------------------------
def execute_here(sources: Sequence[str]) -> dict[str, dict]:
    """Execute (or fetch from the cache) each lesson with this environment's stack;
    source -> {'notebook': path} or {'error': text}.  Runs in the stack's venv."""
    from .execute import LessonExecutionError, publish
    from .lessons import load

    results: dict[str, dict] = {}
    for source in sources:
        try:
            results[source] = {'notebook': str(publish(load(paths.ROOT / source)))}
        except LessonExecutionError as error:
            results[source] = {'error': str(error)}
    return results


def reference_setup(explicit: str | None) -> Path:
    """The setup.bash of the real Jazzy: given, or the shared reference installed."""
    if explicit:
        return Path(explicit).resolve()
    if not REFERENCE_INSTALLER.exists():
        raise SystemExit('parity: no real ROS 2 Jazzy: pass --jazzy /opt/ros/jazzy/setup.bash '
                         f'(or put the reference at {REFERENCE_INSTALLER.parent})')
    done = subprocess.run(['bash', str(REFERENCE_INSTALLER), str(REFERENCE_PREFIX)],
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise SystemExit(f'parity: installing the Jazzy reference failed:\n{done.stderr}')
    return Path(done.stdout.strip().splitlines()[-1])


def without_the_book(environ: Mapping[str, str]) -> dict[str, str]:
    """``environ`` as a shell that never met this checkout has it: no virtual
    environment, no Python, ament or colcon settings, nothing of the checkout on
    PATH (its .venv/bin), so that what is sourced next is all there is."""
    env = {name: value for name, value in environ.items()
           if not name.startswith(('PYTHON', 'AMENT', 'COLCON', 'VIRTUAL_ENV'))}
    env['PATH'] = os.pathsep.join(entry for entry in env.get('PATH', os.defpath).split(os.pathsep)
                                  if not Path(entry).is_relative_to(paths.ROOT))
    return env


def jazzy_environment(setup: Path) -> dict[str, str]:
    """os.environ as after `source SETUP` in a shell :func:`without_the_book`, with
    the build products in build/jazzy, and build/jazzy/venv made (or refreshed) by
    tools/setup_env.sh."""
    clean = without_the_book(os.environ)
    script = f'source {str(setup)!r} >/dev/null && env -0'
    dumped = subprocess.run(['bash', '-c', script], env=clean, capture_output=True,
                            check=True).stdout.decode()
    env = dict(item.split('=', 1) for item in dumped.split('\0') if '=' in item)
    env.update(TEXTBOOK_BUILD=str(JAZZY_BUILD), TEXTBOOK_VENV=str(JAZZY_VENV))
    subprocess.run(['bash', str(paths.TOOLS / 'setup_env.sh')], env=env, check=True)
    return env


def _run_side(python: str, env: dict[str, str] | None, sources: Sequence[str]
              ) -> subprocess.Popen:
    return subprocess.Popen([python, '-m', 'textbook.parity', '--execute-here', *sources],
                            cwd=paths.ROOT, env=env, stdout=subprocess.PIPE, text=True)


def _collect(process: subprocess.Popen, stack: str) -> dict[str, dict]:
    out, _ = process.communicate()
    if process.returncode != 0:
        raise SystemExit(f'parity: executing the lessons on {stack} failed '
                         f'(exit {process.returncode})')
    return json.loads(out.strip().splitlines()[-1])


# -- the command -------------------------------------------------------------------
Result = tuple[Lesson, LessonParity, 'nbformat.NotebookNode | None']


def run(lesson_paths: Sequence[str], jazzy_setup: str | None, stale: bool = False
        ) -> tuple[list[Result], str]:
    """Each lesson (all, or `lesson_paths`) compared on both stacks, with its
    clean-room notebook (None where it did not execute), and the versions of
    the Jazzy compared with (:func:`reference_versions`).  With `stale`, the
    clean room runs first and only the lessons the record no longer covers
    run on Jazzy (none: Jazzy is not even set up)."""
    lessons = load_all()
    if lesson_paths:
        wanted = {Path(p).resolve() for p in lesson_paths}
        lessons = [lesson for lesson in lessons if lesson.path.resolve() in wanted]
    sources = [lesson.source for lesson in lessons]
    if stale:
        ours = _collect(_run_side(sys.executable, None, sources), 'the clean room')
        record = parity_record.load()
        lessons = [lesson for lesson in lessons if 'error' in ours[lesson.source]
                   or not parity_record.status(lesson, _notebook(ours[lesson.source]),
                                               record).held]
        if not lessons:
            return [], ''
        env = jazzy_environment(reference_setup(jazzy_setup))
        theirs = _collect(_run_side(str(JAZZY_VENV / 'bin' / 'python'), env,
                                    [lesson.source for lesson in lessons]), 'Jazzy')
    else:
        env = jazzy_environment(reference_setup(jazzy_setup))
        # Both stacks at once, one lesson each: the two cores the build's `jobs` uses.
        jazzy = _run_side(str(JAZZY_VENV / 'bin' / 'python'), env, sources)
        ours = _collect(_run_side(sys.executable, None, sources), 'the clean room')
        theirs = _collect(jazzy, 'Jazzy')
    allowed = load_allowed()
    results = []
    for lesson in lessons:
        sides = {'clean room': ours[lesson.source], 'Jazzy': theirs[lesson.source]}
        errors = {stack: side['error'] for stack, side in sides.items() if 'error' in side}
        if errors:
            parity = LessonParity(lesson.id, lesson.source, errors=errors)
        else:
            parity = compare(lesson.id, lesson.source, _notebook(sides['clean room']),
                             _notebook(sides['Jazzy']), allowed=allowed)
        results.append((lesson, parity, None if 'error' in sides['clean room']
                        else _notebook(sides['clean room'])))
    return results, reference_versions(env)


def _notebook(side: dict) -> nbformat.NotebookNode:
    return nbformat.read(side['notebook'], as_version=4)


def reference_versions(env: Mapping[str, str]) -> str:
    """The versions of the Jazzy `env` runs: what a record entry was compared with."""
    script = ('import importlib.metadata as m; print(", ".join(f"{n} {m.version(n)}" '
              'for n in ("launch", "launch_ros", "ros2cli", "rclpy")))')
    return subprocess.run([str(JAZZY_VENV / 'bin' / 'python'), '-c', script], env=env,
                          capture_output=True, text=True, check=True).stdout.strip()


def table(report: Sequence[LessonParity]) -> str:
    rows = [f'{"lesson":<34} {"cells":>5} {"differ":>6} {"allowed":>7}  parity']
    for parity in report:
        if parity.errors:
            verdict = '✗ did not run on ' + ' and '.join(parity.errors)
        else:
            verdict = '✓ held' if parity.held else '✗ differs'
        allowed = len(parity.differences) - len(parity.differing)
        rows.append(f'{parity.lesson:<34} {parity.cells:>5} {len(parity.differing):>6} '
                    f'{allowed:>7}  {verdict}')
    return '\n'.join(rows)


def details(report: Sequence[LessonParity], most: int = 40) -> str:
    lines = []
    for parity in report:
        for stack, error in parity.errors.items():
            lines += [f'--- {parity.source}: did not run on {stack}', error]
        for difference in parity.differing:
            first = difference.source.strip().splitlines()[0] if difference.source.strip() else ''
            lines += [f'--- {parity.source}, code cell {difference.cell + 1}: {first}',
                      *difference.diff[:most]]
    return '\n'.join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog='python -m textbook parity', description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('lessons', nargs='*', help='lesson files (default: every lesson)')
    parser.add_argument('--jazzy', metavar='SETUP_BASH',
                        help='setup.bash of a real ROS 2 Jazzy (default: the shared reference)')
    parser.add_argument('--stale', action='store_true',
                        help='only the lessons the parity record no longer covers (their code, '
                             'snippets or clean-room outputs changed since parity held)')
    parser.add_argument('--execute-here', action='store_true', help=argparse.SUPPRESS)
    options = parser.parse_args(argv)
    if options.execute_here:
        print(json.dumps(execute_here(options.lessons)))
        return 0
    results, reference = run(options.lessons, options.jazzy, stale=options.stale)
    report = [parity for _, parity, _ in results]
    REPORT.parent.mkdir(parents=True, exist_ok=True)
    REPORT.write_text(json.dumps([{**asdict(p), 'held': p.held} for p in report], indent=1))
    if results:
        parity_record.update(results, reference)
    print(details(report))
    print(table(report) if report else
          f'parity: every lesson asked for is in {paths.rel(parity_record.RECORD)} as it is now')
    return 0 if all(parity.held for parity in report) else 1


if __name__ == '__main__':
    sys.exit(main())
