"""Every lesson executes through nbclient, as the site build executes it
(one test per lesson).  A lesson whose cache key is unchanged (its text, the
snippets it uses, the tools and the ROS stack) is taken from the cache, as
the site build takes it; ``TEXTBOOK_FRESH=1`` executes every lesson anyway.
Lessons run on any test worker, next to other tests: a lesson spends much of
its time waiting for ROS discovery, and the cache's per-lesson lock keeps a
lesson from being executed twice when the site build wants it too."""
from __future__ import annotations

import pytest
from textbook import execute, settings
from textbook.lessons import discover, load

LESSONS = discover()


def test_there_are_lessons():
    assert LESSONS, 'lessons/ has no lessons'


@pytest.mark.timeout(900)
@pytest.mark.parametrize('path', LESSONS, ids=lambda p: str(p.relative_to(p.parents[2])))
def test_lesson_executes(path):
    lesson = load(path)
    notebook = execute.refresh(lesson) if settings.load().fresh else execute.executed(lesson)
    code_cells = [cell for cell in notebook.cells if cell.cell_type == 'code']
    assert all(cell.get('execution_count') for cell in code_cells), 'a code cell did not run'
    errors = [out for cell in code_cells for out in cell.outputs if out.output_type == 'error']
    assert not errors, errors
