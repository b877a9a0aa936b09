"""Content-addressed cache of executed lessons.

A lesson is executed again only when something that can change its output
changed: its code cells (their source and tags), the snippet packages it
includes or runs, the tools that execute it (this package's execution
code, labkit, the clean-room launch, the pinned packages) or the ROS stack.
Prose is not part of the key: a cached result is merged into the lesson's
current prose (:func:`merge_outputs`), so fixing a typo executes nothing.
"""
from __future__ import annotations

import copy
import fcntl
import functools
import importlib.util
import os
import re
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import nbformat

from . import __version__, paths
from .fingerprint import hash_paths, hash_text
from .lessons import Lesson

LESSON_CACHE = paths.CACHE / 'lessons'
# The parts of this package whose behaviour shows up in executed output.
_EXECUTION_MODULES = ['environment.py', 'execute.py', 'includes.py', 'isolation.py',
                      'lessons.py', 'workspace.py']


def tools_fingerprint() -> str:
    """Changes when the machinery that runs lessons changes."""
    return hash_text(__version__, tools_sources_hash(), ros_stack())


@functools.cache
def tools_sources_hash() -> str:
    """The hash of the execution tools' files, read once per process.

    Every lesson key needs it and reading labkit and the clean room takes
    seconds, while nothing edits tools/ during a build or a test run.  A
    process that outlives such an edit (`textbook serve`, which watches only
    lessons/ and snippets/) keeps the old hash until it restarts; a test that
    edits these files calls `tools_sources_hash.cache_clear()`.
    """
    here = Path(__file__).parent
    sources = [here / name for name in _EXECUTION_MODULES]
    sources += [paths.TOOLS / 'labkit', paths.TOOLS / 'rclhelpers' / 'src',
                paths.TOOLS / 'speccheck' / 'src', paths.TOOLS / 'cleanroom' / 'src',
                paths.ROOT / 'requirements' / 'lock.txt']
    return hash_paths(sources, base=paths.ROOT)


def ros_stack() -> str:
    """Which ROS 2 stack executes lessons: where ``ros2``, ``colcon`` and the
    launch and rclpy packages come from (the clean room in .venv, or a sourced
    ROS 2 installation), so switching stacks in one checkout re-executes."""
    commands = [str(shutil.which(name, path=paths.tool_path())) for name in ('ros2', 'colcon')]
    modules = []
    for name in ('launch', 'launch_ros', 'rclpy'):
        spec = importlib.util.find_spec(name)
        modules.append(str(spec.origin if spec else None))
    return '\n'.join([*commands, *modules, os.environ.get('AMENT_PREFIX_PATH', '')])


def snippet_dependencies(lesson: Lesson, root: Path | None = None) -> list[Path]:
    """Snippet folders/files whose change must re-execute ``lesson``.

    Every package of snippets/ the lesson names (it includes, runs or
    launches from it), every included file, and all of snippets/ for a
    lesson that builds the workspace itself.
    """
    root = root or paths.SNIPPETS
    if re.search(r'\bcolcon\s+build\b', lesson.text):
        return [root]
    return named_snippets(lesson, root)


def named_snippets(lesson: Lesson, root: Path | None = None) -> list[Path]:
    """Every package of snippets/ the lesson names, and every file it includes."""
    root = root or paths.SNIPPETS
    packages = [p for p in sorted(root.iterdir()) if p.is_dir()
                and re.search(rf'\b{re.escape(p.name)}\b', lesson.text)]
    return packages + [s.path for s in lesson.snippets]


def code_text(lesson: Lesson) -> str:
    """What of the lesson is executed: each code cell's tags and source, in order."""
    return '\n'.join(f"{sorted(cell.metadata.get('tags', []))}\n{cell.source}"
                     for cell in lesson.notebook.cells if cell.cell_type == 'code')


def lesson_key(lesson: Lesson, root: Path | None = None) -> str:
    """The cache key of ``lesson`` (``root``: the snippets folder)."""
    deps = snippet_dependencies(lesson, root)
    return hash_text(code_text(lesson), hash_paths(deps, base=(root or paths.SNIPPETS).parent),
                     tools_fingerprint())


def merge_outputs(lesson: Lesson, executed: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The lesson's current notebook (its prose as it is now) with the outputs of
    ``executed``, a run of the same code cells."""
    merged = copy.deepcopy(lesson.notebook)
    ran = [cell for cell in executed.cells if cell.cell_type == 'code']
    mine = [cell for cell in merged.cells if cell.cell_type == 'code']
    if [cell.source for cell in ran] != [cell.source for cell in mine]:
        raise ValueError(f'{lesson.source}: the cached run is of other code cells')
    for cell, result in zip(mine, ran, strict=True):
        cell.outputs = result.outputs
        cell.execution_count = result.execution_count
        cell.metadata = result.metadata
    for key in ('language_info', 'widgets'):
        if key in executed.metadata:
            merged.metadata[key] = executed.metadata[key]
    return merged


def cached(key: str) -> nbformat.NotebookNode | None:
    path = LESSON_CACHE / f'{key}.ipynb'
    return nbformat.read(path, as_version=4) if path.exists() else None


def store(key: str, notebook: nbformat.NotebookNode) -> Path:
    return write_atomic(notebook, LESSON_CACHE / f'{key}.ipynb')


@contextmanager
def exclusive(key: str) -> Iterator[None]:
    """Only one process executes a given lesson version; others wait, then hit the cache."""
    LESSON_CACHE.mkdir(parents=True, exist_ok=True)
    with open(LESSON_CACHE / f'{key}.lock', 'w') as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        yield


def write_atomic(notebook: nbformat.NotebookNode, target: Path) -> Path:
    """Write so that a reader never sees half a notebook (serve and tests run at once)."""
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=target.parent, suffix='.tmp')
    with os.fdopen(fd, 'w') as handle:
        nbformat.write(notebook, handle)
    os.replace(tmp, target)
    return target
