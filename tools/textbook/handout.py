"""The notebook an instructor hands out: the executed lesson without its solutions.

The page offers two downloads: the executed notebook as the book runs it,
and this copy without the cells tagged ``solution`` (the prose and code that
the page folds away), so the page can be handed to students as it is and
their exercise checks grade their own work.  Everything else stays as
executed, hints included.
"""
from __future__ import annotations

import copy

import nbformat

#: How the handout of ``lesson.ipynb`` is named, beside it: ``lesson.no-solutions.ipynb``.
SUFFIX = '.no-solutions.ipynb'


def without_solutions(notebook: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """A copy of ``notebook`` without its ``solution`` cells."""
    handout = copy.deepcopy(notebook)
    handout.cells = [cell for cell in handout.cells
                     if 'solution' not in cell.get('metadata', {}).get('tags', [])]
    return handout


def handout_name(notebook_name: str) -> str:
    """``00_setup_check.ipynb`` -> ``00_setup_check.no-solutions.ipynb``."""
    return notebook_name.removesuffix('.ipynb') + SUFFIX
