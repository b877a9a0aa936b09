"""Every exercise check, proven both ways: it fails on the untouched starter
and on each catalogued wrong answer (naming the mistake), and passes on the
book's solution.  The passing side is the lesson's own evidence: the book's
build applies each solution and its check cell raises when the check fails
(labkit.exercises.check), so tests/lessons executing the lesson proves it;
grading the solution here again would launch the same system twice.
test_every_exercise_is_solved_and_checked_in_a_lesson keeps that true.

The book's snippets workspace (built once) is the underlay; each exercise
gets its own overlay workspace, built on first use, holding one copy of the
student's package per case (`ex_starter`, `ex_wrong_<n>`).
A student's overlay on a sourced workspace works the same way, and
`-k ex611` builds only what exercise 6.11 needs.
Each check launches its case as a student's terminal would, from a process
of its own, killed with its stacks kept if it hangs inside DDS (_grading_process).  New exercises
and wrong answers are picked up from labkit.checks and
`snippets/<solutions>/wrong/` without touching this file.
"""
from __future__ import annotations

import os
import subprocess
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
from labkit import checks, exercises, observer
from labkit.grading.student_package import PACKAGE, StudentPackage
from textbook import paths, workspace
from textbook.isolation import holding_fixed_domains

from . import _grading_process as grading_process


@dataclass(frozen=True)
class Case:
    exercise: str
    kind: str  # 'starter' or 'wrong' (the solution: see the module docstring)
    name: str = ''
    package: str = ''

    def __str__(self) -> str:
        return f'{self.exercise}-{self.kind}' + (f'-{self.name}' if self.name else '')


def _cases() -> list[Case]:
    cases = []
    for exercise in checks.EXERCISES.values():
        cases.append(Case(exercise.id, 'starter', package='ex_starter'))
        for number, name in enumerate(exercise.wrong_answers()):
            cases.append(Case(exercise.id, 'wrong', name, f'ex_wrong_{exercise.id}_{number}'))
    return cases


CASES = _cases()
#: Exercises whose launch puts a node into a domain by number (6.7's right sensor
#: in 101): a case holds it, so that the lesson's run never meets its sensor.
FIXED_DOMAINS = {'ex67_fix_pipeline': (101,)}


def _expected_phrases(case: Case) -> list[str]:
    return list(checks.find(case.exercise).wrong_answer_patches()[case.name].verdict_names)


@pytest.fixture(scope='module')
def lesson_environment():
    """os.environ as in a lesson kernel: this process's ROS domain, the project's
    tools first on PATH, and no solution applied behind the checks' back."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv('PATH', f"{paths.VENV_BIN}:{os.environ.get('PATH', '')}")
        patch.delenv(exercises.APPLY_SOLUTIONS, raising=False)
        yield


def _colcon_build(workspace: Path, env: dict[str, str] | None = None) -> None:
    result = subprocess.run([paths.executable('colcon'), 'build'], cwd=workspace, env=env,
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.fixture(scope='module')
def book_underlay(lesson_environment) -> StudentPackage:
    """The book's snippets workspace (built once per session for every test that needs
    it): the underlay every exercise workspace sources, as a lesson's workspace has
    the book's packages next to the student's."""
    return StudentPackage(workspace.ensure_built().resolve().parent)


@pytest.fixture(scope='module')
def exercise_workspaces(tmp_path_factory, book_underlay: StudentPackage
                        ) -> Callable[[str], Path]:
    """exercise id -> its overlay workspace with every case of it, built on first use."""
    built: dict[str, Path] = {}

    def workspace_of(exercise_id: str) -> Path:
        if exercise_id not in built:
            built[exercise_id] = _build_cases(
                tmp_path_factory.mktemp(f'exercise_{exercise_id}'), exercise_id,
                book_underlay.environment())
        return built[exercise_id]

    return workspace_of


def _build_cases(workspace: Path, exercise_id: str, underlay: dict[str, str]) -> Path:
    """The cases of one exercise, each a whole student package as the book's
    lessons leave it: every exercise's starter files (an exercise may build on an
    earlier one's file, as 6.2.2 on 6.2.1's), and each wrong answer over the starters."""
    ids = list(checks.EXERCISES)
    exercises.setup(*ids, workspace=workspace, package='ex_starter')
    for case in CASES:
        if case.kind == 'wrong' and case.exercise == exercise_id:
            exercises.setup(*ids, workspace=workspace, package=case.package)
            answer = checks.find(exercise_id).wrong_answers()[case.name]
            for relative, text in answer.items():  # named for its package, like the rest
                target = workspace / 'src' / case.package / relative
                target.parent.mkdir(parents=True, exist_ok=True)
                target.write_text(text.replace(PACKAGE, case.package))
    _colcon_build(workspace, underlay)
    return workspace


def test_every_exercise_has_wrong_answers_that_say_what_the_check_reports():
    assert checks.EXERCISES
    for exercise in checks.EXERCISES.values():
        answers = exercise.wrong_answers()
        assert answers, f'{exercise.id} has no catalogue of wrong answers'
        for name in answers:
            assert _expected_phrases(Case(exercise.id, 'wrong', name)), \
                f'wrong answer {exercise.id}/{name} has no "# Verdict names: ..." line'


def _on_one_worker(case: Case) -> object:
    """The cases of one exercise share a test worker, so its workspace is built once."""
    return pytest.param(case, id=str(case), marks=pytest.mark.xdist_group(case.exercise))


@pytest.mark.timeout(900)
@pytest.mark.parametrize('case', [_on_one_worker(case) for case in CASES])
def test_check_fails_on_starter_and_wrong_answers(
        case: Case, exercise_workspaces: Callable[[str], Path], lesson_environment):
    workspace = exercise_workspaces(case.exercise)
    # This process watches nothing while the case runs: its observer would only
    # see the case's launches stop (see _grading_process).
    observer.close()
    with holding_fixed_domains(FIXED_DOMAINS.get(case.exercise, ())):
        verdict = grading_process.grade(case.exercise, workspace, case.package)
    report = str(verdict)
    print(report)  # in the test log: what a student would read
    assert not verdict.passed and verdict.problems, report
    for phrase in _expected_phrases(case) if case.kind == 'wrong' else []:
        assert phrase in report, f'the verdict should name {phrase!r}:\n{report}'


def test_a_file_changed_after_the_build_is_reported_before_anything_runs(
        exercise_workspaces: Callable[[str], Path], lesson_environment):
    exercise = checks.find('ex61_full_pipeline')
    workspace = exercise_workspaces(exercise.id)
    source = workspace / 'src' / 'ex_starter' / exercise.files[0]
    original = source.read_bytes()
    source.write_bytes(original + b'# an edit not built yet\n')
    try:
        verdict = exercise.grade(StudentPackage(workspace, 'ex_starter'))
    finally:
        source.write_bytes(original)
    assert verdict.problems == [
        'src/ex_starter/launch/ex61_full_pipeline.launch.py is newer than the installed copy: '
        'run colcon build --packages-select ex_starter']
