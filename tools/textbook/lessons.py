"""Lessons: discovery, reading (jupytext MyST) and every check that needs no kernel.

A lesson is ``lessons/ch<NN>/<layer>/<name>.md``.  Loading it validates its
metadata, rejects inline launch/parameter/package code, and expands snippet
includes, so a broken lesson fails before anything is executed.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import jupytext
import nbformat

from . import inline_check, keypoints, metadata, paths
from .includes import Snippet, expand
from .tabs import check_markdown


@dataclass
class Lesson:
    path: Path
    text: str
    meta: dict[str, Any]
    notebook: nbformat.NotebookNode
    snippets: list[Snippet] = field(default_factory=list)

    @property
    def source(self) -> str:
        """The repository-relative path, as errors name it."""
        return paths.rel(self.path)

    @property
    def id(self) -> str:
        return self.meta['id']

    @property
    def title(self) -> str:
        return self.meta['title']

    @property
    def site_path(self) -> str:
        """Where the executed notebook lives in the site, e.g. ``ch06/L1/00_setup.ipynb``."""
        return f"ch{self.meta['chapter']:02d}/{self.meta['layer']}/{self.path.stem}.ipynb"


def discover(root: Path = paths.LESSONS) -> list[Path]:
    """Every lesson file, in reading order (chapter, layer, file name)."""
    if not root.is_dir():
        return []
    return sorted(p for p in root.rglob('*.md')
                  if p.name.lower() != 'readme.md' and not p.name.startswith(('_', '.')))


def load(path: Path) -> Lesson:
    """Read and check one lesson; raises a ValueError subclass naming file and line."""
    path = Path(path).resolve()
    source = paths.rel(path)
    text = path.read_text()
    inline_check.check(text, source)
    expanded, used = expand(text, source)
    notebook = jupytext.reads(expanded, fmt='md:myst')
    meta = metadata.validate(notebook.metadata.get('textbook'), source)
    metadata.check_location(meta, path, source)
    keypoints.check(text, source)
    notebook.metadata['kernelspec'] = {'name': 'python3', 'display_name': 'Python 3',
                                       'language': 'python'}
    notebook.metadata.pop('jupytext', None)
    for index, cell in enumerate(notebook.cells):  # the same lesson, the same notebook
        cell.id = f'cell-{index}'
        if cell.cell_type == 'markdown':
            first_line = cell.source.strip().splitlines()[0] if cell.source.strip() else ''
            check_markdown(cell.source, f'{source}: the markdown cell that begins {first_line!r}')
    return Lesson(path, text, meta, notebook, used)


def load_all(root: Path = paths.LESSONS) -> list[Lesson]:
    """Load every lesson, reporting all broken ones at once, then cross-check them."""
    lessons, problems = [], []
    for path in discover(root):
        try:
            lessons.append(load(path))
        except ValueError as error:
            problems.append(str(error))
    if problems:
        raise LessonError('\n'.join(problems))
    metadata.check_collection({lesson.source: lesson.meta for lesson in lessons})
    return lessons


class LessonError(ValueError):
    """One or more lessons failed their checks."""
