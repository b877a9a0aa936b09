"""Findings carry a stable code, the spec line they come from and a fix hint (for the
JSON, JUnit and SARIF reports); the text report stays as lessons print it; the
command's exit codes are 0 met, 1 not met, 2 could not judge."""
from __future__ import annotations

import speccheck.static_check
from speccheck import Status, check_static, codes, load_spec
from speccheck.__main__ import EXIT_CODES, build_parser, main

from tests.speccheck.conftest import LAUNCH_FILES

SPEC = LAUNCH_FILES / 'scoped.yaml'
LAUNCH = LAUNCH_FILES / 'scoped.launch.py'


def located(report):
    """(status, code, spec line) of each finding that is not met."""
    return [(f.status, f.rule, f.line) for f in report.findings if f.status is not Status.MET]


def test_findings_name_their_code_and_spec_line(sourced):
    report = check_static(load_spec(SPEC), LAUNCH)
    NOT_CHECKED, FAILED = Status.NOT_CHECKED, Status.FAILED
    assert located(report) == [
        (NOT_CHECKED, 'NotChecked', 12),  # max_linear_speed: not set by the launch file
        (FAILED, 'UnexpectedParameter', 10),  # max_linear_sped: under `parameters:` of /controller
        (FAILED, 'PublisherMissing', 20),  # /scan's publishers: [/robot1/lidar]
        *[(NOT_CHECKED, 'NotChecked', 1)] * 3,  # OpaqueFunction, TimerAction, event handler
    ]
    met = report.find('node /robot1/filter: parameter window_size')[0]
    assert (met.code, met.line, met.hint) == (None, 7, '')
    failed = report.find('topic /scan: publisher')[0]
    assert failed.hint == codes.HINTS['PublisherMissing'] and failed.hint


def test_missing_unexpected_and_mismatched_requirements(installed, write_spec):
    spec = load_spec(write_spec(
        'nodes:\n'
        '  /sensor_publisher: {package: other_pkg}\n'
        '  /lidar: {}\n'
        'arguments:\n'
        '  robot_name: {}\n'))
    report = check_static(spec, installed('robot_system.launch.py'), {'robot_nme': 'x'})
    found = {(f.requirement, f.rule, f.line) for f in report.findings
             if f.status is Status.FAILED}
    assert found == {
        ('argument robot_nme', 'UnexpectedArgument', 1),
        ('argument robot_name', 'ArgumentMissing', 5),
        ('node /sensor_publisher', 'NodeMismatch', 2),
        ('node /lidar', 'NodeMissing', 3),
        ('node /data_processor', 'UnexpectedNode', 1),
    }


def test_every_code_has_a_one_line_hint():
    names = [value for name, value in vars(codes).items() if name.isupper() and
             isinstance(value, str)]
    assert set(names) == set(codes.HINTS) and len(names) == 20
    assert {'NodeMissing', 'UnexpectedNode', 'TopicMissing', 'TypeMismatch', 'QoSMismatch',
            'ParameterMissing', 'ParameterMismatch'} <= set(names)
    assert all(hint and '\n' not in hint for hint in codes.HINTS.values())


def test_the_text_report_shows_no_codes(sourced):
    text = str(check_static(load_spec(SPEC), LAUNCH))
    assert '  FAILED      topic /scan: publisher /robot1/lidar: remap distance:=scan gives ' \
           '/robot1/scan, not /scan' in text.splitlines()
    assert not any(code in text for code in codes.HINTS)


def test_help_documents_the_exit_codes():
    text = ' '.join(build_parser().format_help().split())
    assert sorted(EXIT_CODES) == [0, 1, 2]
    for code, meaning in EXIT_CODES.items():
        assert f'{code} {" ".join(meaning.split())}' in text
    assert '1 not met' in text and '2 could not judge' in text


def test_a_check_that_crashes_could_not_judge(monkeypatch, capsys):
    def crash(*_args):
        raise RuntimeError('the launch walk broke')
    monkeypatch.setattr(speccheck.static_check, 'check_static', crash)
    assert main(['static', str(SPEC), str(LAUNCH)]) == 2
    captured = capsys.readouterr()
    assert captured.out == ''
    assert captured.err.rstrip().endswith(
        'speccheck: error: could not judge: RuntimeError: the launch walk broke')
