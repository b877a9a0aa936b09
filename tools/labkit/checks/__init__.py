"""Every exercise of the book, by id; each chapter's checks live in a module
of this package (`ch06_01.py` for lesson 6.1) that lists its EXERCISES."""
from __future__ import annotations

from labkit.checks import ch06_01
from labkit.errors import LabkitError
from labkit.grading.exercise import Exercise

EXERCISES: dict[str, Exercise] = {exercise.id: exercise for exercise in (
    *ch06_01.EXERCISES,
)}


def find(exercise_id: str) -> Exercise:
    """The exercise called `exercise_id`, or an error listing the known ones."""
    try:
        return EXERCISES[exercise_id]
    except KeyError:
        raise LabkitError(f'no exercise {exercise_id!r}; known: '
                          f'{", ".join(sorted(EXERCISES))}') from None
