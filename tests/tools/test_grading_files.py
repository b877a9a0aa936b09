"""labkit.grading: an exercise lists its files once; files_installed reads them from there."""
from __future__ import annotations

from pathlib import Path

import pytest
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

LAUNCH = 'launch/ex_demo.launch.py'
CONFIG = 'config/ex_demo.yaml'


def _check(package: StudentPackage, verdict: Verdict) -> Verdict:
    """A check that names no file: it relies on the exercise's list."""
    requirements.files_installed(verdict, package)
    return verdict


EXERCISE = Exercise('ex_demo', 'Exercise 0.0.1 (demo)', (LAUNCH, CONFIG), _check)


def _package(workspace: Path, installed: dict[str, str], source: dict[str, str]) -> StudentPackage:
    package = StudentPackage(workspace)
    for root, files in ((package.source, source), (package.share, installed)):
        for relative, text in files.items():
            (root / relative).parent.mkdir(parents=True, exist_ok=True)
            (root / relative).write_text(text)
    return package


def test_the_exercises_files_are_the_ones_checked(tmp_path):
    both = {LAUNCH: 'launch\n', CONFIG: 'config\n'}
    verdict = EXERCISE.grade(_package(tmp_path / 'built', both, both))
    assert verdict.passed
    assert [sentence for _, sentence in verdict.results] == [
        'src/my_ws_exercises/launch/ex_demo.launch.py is built and installed',
        'src/my_ws_exercises/config/ex_demo.yaml is built and installed']


def test_a_file_of_the_exercise_not_built_fails(tmp_path):
    package = _package(tmp_path / 'half', {LAUNCH: 'launch\n'},
                       {LAUNCH: 'launch\n', CONFIG: 'config\n'})
    verdict = EXERCISE.grade(package)
    assert not verdict.passed
    (problem,) = verdict.problems
    assert 'ex_demo.yaml is not installed' in problem


def test_outside_an_exercise_the_files_must_be_given(tmp_path):
    with pytest.raises(TypeError, match='needs `files`'):
        requirements.files_installed(Verdict('loose'), StudentPackage(tmp_path))
