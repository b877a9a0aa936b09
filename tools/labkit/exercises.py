"""Exercises that grade the student's own package: the calls a lesson makes.

    labkit.exercises.setup('ex61_full_pipeline', 'ex61_front_sensor')  # starter files
    labkit.exercises.solution('ex61_full_pipeline')   # cell tagged `solution`
    labkit.exercises.check('ex61_full_pipeline')      # after colcon build

The student works in `src/my_ws_exercises/` of the workspace the notebook
runs in (the current folder).  `setup` never overwrites a file; `solution`
copies the book's solution only in the book's build (TEXTBOOK_APPLY_SOLUTIONS=1),
and `check` raises there when the check fails.  See
EXERCISES.md.
"""
from __future__ import annotations

import os
from pathlib import Path

from labkit import checks
from labkit.errors import LabkitError
from labkit.grading.exercise import SNIPPETS, STARTERS
from labkit.grading.student_package import PACKAGE, StudentPackage
from labkit.grading.verdict import ExerciseNotSolved, Verdict
from labkit.workspace import require_snippets

#: Set to 1 by the book's build: solution cells apply the solution, and a
#: check that fails fails the build.
APPLY_SOLUTIONS = 'TEXTBOOK_APPLY_SOLUTIONS'


def _book_build() -> bool:
    return os.environ.get(APPLY_SOLUTIONS) == '1'


def _package(workspace: str | os.PathLike | None, package: str) -> StudentPackage:
    return StudentPackage(Path(workspace or Path.cwd()).resolve(), package)


def copy_for_package(source: Path, target: Path, package: str) -> None:
    """Copy a starter or solution file, naming the package `package`."""
    target.parent.mkdir(parents=True, exist_ok=True)
    data = source.read_bytes()
    if package != PACKAGE:
        data = data.replace(PACKAGE.encode(), package.encode())
    target.write_bytes(data)


def _skeleton() -> list[str]:
    """Starter files that belong to no exercise: package.xml, setup.py, ..."""
    owned = {f for exercise in checks.EXERCISES.values() for f in exercise.files}
    return [str(f.relative_to(STARTERS)) for f in sorted(STARTERS.rglob('*'))
            if f.is_file() and '__pycache__' not in f.parts
            and str(f.relative_to(STARTERS)) not in owned]


def setup(*exercise_ids: str, workspace: str | os.PathLike | None = None,
          package: str = PACKAGE) -> None:
    """Create `src/my_ws_exercises/` with the starter files of these exercises.

    Only files that do not exist yet are written: your work is never
    overwritten, and a later lesson adds its own starter files next to it.
    Prints each file created or kept (returns nothing, so a notebook shows
    only that list).
    """
    require_snippets(SNIPPETS)
    target = _package(workspace, package)
    wanted = _skeleton() + [f for i in exercise_ids for f in checks.find(i).files]
    created = []
    for relative in wanted:
        destination = target.source / relative.replace(PACKAGE, package)
        if not destination.exists():
            copy_for_package(STARTERS / relative, destination, package)
            created.append(destination)
    for relative in wanted:
        path = target.source / relative.replace(PACKAGE, package)
        state = 'created' if path in created else 'kept (already there)'
        if relative.endswith('.launch.py') or path in created:
            print(f'{target.shown(path)}: {state}')


def use_solution(exercise_id: str, force: bool = False,
                 workspace: str | os.PathLike | None = None, package: str = PACKAGE,
                 ) -> list[Path]:
    """Copy the book's solution of an exercise into your package, on purpose.

    Without `force=True` a file you changed (it differs from the starter)
    is not overwritten.  Build afterwards: colcon build --packages-select my_ws_exercises
    """
    require_snippets(SNIPPETS)
    exercise = checks.find(exercise_id)
    target = _package(workspace, package)
    copied = []
    for relative in exercise.files:
        destination = target.source / relative
        if destination.exists() and not force \
                and destination.read_bytes() != exercise.starter(relative).read_bytes():
            raise LabkitError(f'{target.shown(destination)} holds your own work; to replace it '
                              f"with the book's solution call "
                              f"labkit.exercises.use_solution({exercise_id!r}, force=True)")
        copy_for_package(exercise.solution(relative), destination, package)
        print(f'{exercise.solution(relative).relative_to(STARTERS.parents[1])} -> '
              f'{target.shown(destination)}')
        copied.append(destination)
    return copied


def solution(exercise_id: str, workspace: str | os.PathLike | None = None,
             package: str = PACKAGE) -> None:
    """The solution cell: applies the solution in the book's build only.

    In your own notebook it changes nothing, so "Run all" keeps your work.
    """
    if _book_build():
        use_solution(exercise_id, force=True, workspace=workspace, package=package)
        return
    print(f'Your files are unchanged. To replace them with the solution on purpose:\n'
          f'    labkit.exercises.use_solution({exercise_id!r}, force=True)')


def check(exercise_id: str, workspace: str | os.PathLike | None = None,
          package: str = PACKAGE) -> Verdict:
    """Grade your package: launches your file, looks at the graph and the log.

    Returns the verdict (a notebook shows it); in the book's build an
    unsolved exercise raises ExerciseNotSolved, so a broken solution fails CI.
    """
    verdict = checks.find(exercise_id).grade(_package(workspace, package))
    if _book_build() and not verdict.passed:
        raise ExerciseNotSolved(str(verdict))
    return verdict
