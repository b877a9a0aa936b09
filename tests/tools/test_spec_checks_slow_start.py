"""The checks of 7.1.1 and 7.4 when a system is slow to start: a wait for nodes
the system does run is no verdict on the student's spec (CI once graded 7.1.1's
nodes-only wrong answer as solved because turtle3_other_config.launch.py had
not started /turtle3/controller within speccheck's 20 s).  speccheck stands in
here; tests/speccheck/test_report_and_cli.py shows that `SpecRun.not_started`
reads the real one's report."""
from __future__ import annotations

from pathlib import Path

import pytest
from labkit.checks import ch07_01, ch07_04
from labkit.grading import spec_run
from labkit.grading.spec_run import SpecRun
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

from ._student_package import with_empty_spec

CAPSTONE_3, CAPSTONE_2 = 'robot_count:=3', 'robot_count:=2'
OTHER_CONFIG = ch07_01.DEFECT.name


def passed() -> tuple[int, str]:
    return 0, 'speccheck live: x against s\n  met         node /turtle3/controller: running\n' \
        'PASSED: 1 met, 0 failed, 0 not checked\n'


def found(finding: str) -> tuple[int, str]:
    return 1, f'speccheck live: x against s\n  FAILED      {finding}\n' \
        'FAILED: 0 met, 1 failed, 0 not checked\n'


def timed_out(*nodes: str) -> tuple[int, str]:
    """speccheck's report when its wait ran out (labkit's words, as the CLI test shows)."""
    kind = 'node' if len(nodes) == 1 else 'nodes'
    return 1, (f'speccheck live: x against s\n  FAILED      launch: Timed out after 20 s waiting '
               f'for {kind} {", ".join(nodes)} from `ros2 launch x`.\n'
               'Nodes in the graph: /turtlesim, /turtle3/wall_sensor.\n'
               'Last lines of its output:\n[INFO] [controller-16]: process started\n'
               'FAILED: 0 met, 1 failed, 0 not checked\n')


VALUE = 'node /turtle3/safety_monitor: parameter stop_distance: value 1.0, the spec says 0.8'


class Speccheck:
    """Stands in for `speccheck live`: answers per system, in order, and
    records each command line."""

    def __init__(self, answers: dict[str, list[tuple[int, str]]]):
        self.answers = answers
        self.targets: list[list[str]] = []

    def __call__(self, package, mode, spec, target, shown, env=None) -> SpecRun:
        self.targets.append(target)
        system = next(key for key in self.answers if key in ' '.join(target))
        code, stdout = self.answers[system].pop(0)
        if '--timeout' in target:  # the wait it reports is the one it was given
            seconds = target[target.index('--timeout') + 1]
            stdout = stdout.replace('Timed out after 20 s', f'Timed out after {seconds} s')
        return SpecRun(shown, code, stdout, '')


@pytest.fixture
def package(tmp_path: Path) -> StudentPackage:
    return with_empty_spec(tmp_path, ch07_01.SPEC)


def grade(package: StudentPackage, speccheck: Speccheck,
          monkeypatch: pytest.MonkeyPatch) -> Verdict:
    monkeypatch.setattr(spec_run, 'run_speccheck', speccheck)
    return ch07_01.check_third_robot(package, Verdict('7.1.1'))


def test_a_slow_start_is_waited_for_longer_before_the_spec_is_judged(package, monkeypatch):
    speccheck = Speccheck({CAPSTONE_3: [timed_out('/turtle3/controller'), passed()],
                           CAPSTONE_2: [timed_out('/turtle3/controller')],
                           OTHER_CONFIG: [timed_out('/turtle3/controller'), passed()]})
    verdict = grade(package, speccheck, monkeypatch)
    # the defect with turtle3's nodes running and passing is not caught, however slow
    assert not verdict.passed
    assert verdict.problems == [f'your spec passes {OTHER_CONFIG}, where '
                                f'{ch07_01.DEFECTS[1].defect}: {ch07_01.DEFECTS[1].need}']
    longer = ['--timeout', str(spec_run.SLOW_START)]
    assert [target[:2] == longer for target in speccheck.targets] == \
        [False, True, False, False, True]
    # robot_count:=2 has no turtle3: the wait that ran out is the catch, not repeated
    assert f'the running check catches capstone.launch.py {CAPSTONE_2}' in str(verdict)


def test_a_value_found_after_the_longer_wait_is_the_catch(package, monkeypatch):
    speccheck = Speccheck({CAPSTONE_3: [passed()], CAPSTONE_2: [timed_out('/turtle3/controller')],
                           OTHER_CONFIG: [timed_out('/turtle3/controller'), found(VALUE)]})
    verdict = grade(package, speccheck, monkeypatch)
    assert verdict.passed, verdict
    assert f'the running check catches {OTHER_CONFIG}' in str(verdict)
    assert VALUE in str(verdict)


def test_a_system_that_never_starts_is_reported_not_caught(package, monkeypatch):
    speccheck = Speccheck({CAPSTONE_3: [passed()], CAPSTONE_2: [timed_out('/turtle3/controller')],
                           OTHER_CONFIG: [timed_out('/turtle3/controller')] * 2})
    verdict = grade(package, speccheck, monkeypatch)
    assert not verdict.passed
    [problem] = verdict.problems
    assert problem.startswith(
        f'`speccheck live src/my_ws_exercises/{ch07_01.SPEC} --timeout '
        f'{spec_run.SLOW_START} {ch07_01.DEFECT}` did not start /turtle3/controller within '
        f'{spec_run.SLOW_START} s, so your spec was not judged on {OTHER_CONFIG}')
    assert 'Nodes in the graph: /turtlesim, /turtle3/wall_sensor.' in problem
    assert '[INFO] [controller-16]: process started' in problem


def test_the_system_meeting_r9_not_started_is_not_blamed_on_the_spec(package, monkeypatch):
    speccheck = Speccheck({CAPSTONE_3: [timed_out('/turtle3/controller')] * 2})
    verdict = grade(package, speccheck, monkeypatch)
    [problem] = verdict.problems
    assert 'did not start /turtle3/controller within' in problem
    assert 'fails with your spec' not in problem


def test_nodes_the_system_does_not_run_end_the_wait_at_once(package, monkeypatch):
    """A bare /controller (no namespace) never appears: no longer wait, the spec is wrong."""
    speccheck = Speccheck({CAPSTONE_3: [timed_out('/controller', '/turtle3/controller')]})
    verdict = grade(package, speccheck, monkeypatch)
    assert len(speccheck.targets) == 1
    [problem] = verdict.problems
    assert 'fails with your spec: your spec names nodes or topics the system does not have' \
        in problem


def test_the_night_shift_defect_not_started_is_not_caught(package, monkeypatch):
    capstone = ' '.join(ch07_04.DEFECT)
    speccheck = Speccheck({capstone: [timed_out('/turtle3/controller')] * 2})
    monkeypatch.setattr(spec_run, 'run_speccheck', speccheck)
    verdict = Verdict('7.4')
    ch07_04._spec_catches_defect(verdict, package)
    [problem] = verdict.problems
    assert f'did not start /turtle3/controller within {spec_run.SLOW_START} s, so your spec ' \
        f'was not judged on {ch07_04.DEFECT_SHOWN}' in problem
    assert [target[:2] for target in speccheck.targets] == \
        [['--launch', 'capstone_bringup'], ['--timeout', str(spec_run.SLOW_START)]]


def test_a_run_that_fails_without_a_finding_is_quoted_not_left_empty(package, monkeypatch):
    """CI once graded 7.1.1 with "`speccheck live ...` reported:" and nothing after it:
    speccheck had ended non-zero without a FAILED line.  Its exit code and last lines
    are the report then."""
    crash = (1, 'speccheck live: x against s\n')
    speccheck = Speccheck({CAPSTONE_3: [crash], CAPSTONE_2: [timed_out('/turtle3/controller')],
                           OTHER_CONFIG: [found(VALUE)]})
    verdict = grade(package, speccheck, monkeypatch)
    [problem] = verdict.problems
    assert problem.endswith('reported:\n      (exit code 1, no finding; its last lines:)\n'
                            '      speccheck live: x against s'), problem
    assert SpecRun('s', -9, '', 'Traceback (most recent call last):\nKeyError: 1\n') \
        .shown_findings(2) == ('(exit code -9, no finding; its last lines:)\n'
                               '      Traceback (most recent call last):\n      KeyError: 1')
