"""Check 7.4 starts the day shift once: the student's spec is checked against
that running launch (`speccheck live SPEC`, no launch of its own), and only
when the launch runs every node the brief asks for.  speccheck stands in here."""
from __future__ import annotations

from pathlib import Path

import pytest
from labkit.checks import ch07_04
from labkit.grading import spec_run
from labkit.grading.launch_probe import LaunchProbe
from labkit.grading.spec_run import SpecRun
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot

from ._student_package import with_empty_spec

PASSED = 'speccheck live: x against s\nPASSED: 19 met, 0 failed, 0 not checked\n'


@pytest.fixture
def package(tmp_path: Path) -> StudentPackage:
    return with_empty_spec(tmp_path, ch07_04.SPEC)


@pytest.fixture
def targets(monkeypatch) -> list[list[str]]:
    """The targets speccheck was run with (it passes every time)."""
    runs: list[list[str]] = []

    def speccheck(package, mode, spec, target, shown, env=None) -> SpecRun:
        runs.append(target)
        return SpecRun(shown, 0, PASSED, '')

    monkeypatch.setattr(spec_run, 'run_speccheck', speccheck)
    monkeypatch.setattr(ch07_04, 'read_values', lambda snapshot: {})
    return runs


def _inspect(package: StudentPackage, shift: str, nodes: tuple[str, ...]) -> ch07_04.Shift:
    return ch07_04._inspect(package, shift)(GraphSnapshot(nodes, {}))


def test_the_spec_is_checked_against_the_running_day_shift(package, targets):
    day = _inspect(package, 'day', ch07_04.EXPECTED_NODES)
    assert targets == [[]]  # the running graph: no --launch, no second system
    assert day.spec is not None
    assert day.spec.command == f'speccheck live src/my_ws_exercises/{ch07_04.SPEC}'
    run = LaunchProbe('ros2 launch my_ws_exercises night_shift.launch.py', [], None, False,
                      None, inspected=day)
    verdict = Verdict('7.4')
    assert ch07_04._spec_passes(verdict, package, run)
    assert 'your spec passes your running system (PASSED: 19 met' in str(verdict)


def test_no_spec_run_for_the_night_shift_or_a_system_not_all_up(package, targets):
    assert _inspect(package, 'night', ch07_04.EXPECTED_NODES).spec is None
    assert _inspect(package, 'day', ch07_04.EXPECTED_NODES[:-1]).spec is None
    assert targets == []
