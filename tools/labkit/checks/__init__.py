"""Every exercise of the book, by id.

Each lesson's checks live in a module of this package named after it
(`ch06_01.py` for lesson 6.1) that lists its `EXERCISES`; every such module
is picked up here, so adding a lesson's checks touches no other file.
"""
from __future__ import annotations

import importlib
import pkgutil

from labkit.errors import LabkitError
from labkit.grading.exercise import Exercise


def _lesson_modules() -> list:
    names = sorted(info.name for info in pkgutil.iter_modules(__path__)
                   if info.name.startswith('ch'))
    return [importlib.import_module(f'{__name__}.{name}') for name in names]


EXERCISES: dict[str, Exercise] = {exercise.id: exercise for module in _lesson_modules()
                                  for exercise in module.EXERCISES}


def find(exercise_id: str) -> Exercise:
    """The exercise called `exercise_id`, or an error listing the known ones."""
    try:
        return EXERCISES[exercise_id]
    except KeyError:
        raise LabkitError(f'no exercise {exercise_id!r}; known: '
                          f'{", ".join(sorted(EXERCISES))}') from None
