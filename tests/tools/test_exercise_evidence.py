"""The executed lessons are the evidence that every exercise's check passes on
the book's solution (tests/exercises grades only the starter and the wrong
answers): each exercise has a solution cell and, after it, a check cell in a
lesson, and in the book's build a check that fails raises, failing the lesson."""
from __future__ import annotations

import pytest
from labkit import checks, exercises
from labkit.grading.verdict import ExerciseNotSolved, Verdict
from textbook.lessons import discover, load


def _code_cells() -> list[tuple[str, str, list[str]]]:
    """(lesson, source, tags) of every code cell of every lesson, in reading order."""
    cells = []
    for path in discover():
        lesson = load(path)
        cells += [(lesson.source, cell.source.strip(), cell.metadata.get('tags', []))
                  for cell in lesson.notebook.cells if cell.cell_type == 'code']
    return cells


def test_every_exercise_is_solved_and_checked_in_a_lesson():
    cells = _code_cells()
    missing = []
    for exercise in checks.EXERCISES:
        solution = f'labkit.exercises.solution({exercise!r})'
        check = f'labkit.exercises.check({exercise!r})'
        where = [i for i, (_, source, tags) in enumerate(cells)
                 if source == solution and 'solution' in tags]
        checked = [i for i, (_, source, _) in enumerate(cells) if source == check]
        if not where or not any(c > where[0] and cells[c][0] == cells[where[0]][0]
                                for c in checked):
            missing.append(exercise)
    assert not missing, f'no lesson applies the solution and then checks: {missing}'


class _Failing:
    def grade(self, package) -> Verdict:
        return Verdict('An exercise', [(False, 'the node is missing')])


def test_in_the_books_build_a_check_that_fails_raises(monkeypatch, tmp_path):
    monkeypatch.setattr(checks, 'find', lambda exercise_id: _Failing())
    monkeypatch.setenv(exercises.APPLY_SOLUTIONS, '1')
    with pytest.raises(ExerciseNotSolved, match='the node is missing'):
        exercises.check('ex60_talk', workspace=tmp_path)
    monkeypatch.delenv(exercises.APPLY_SOLUTIONS)
    assert not exercises.check('ex60_talk', workspace=tmp_path).passed
