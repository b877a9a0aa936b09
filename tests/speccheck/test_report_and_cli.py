"""The report in text, markdown and HTML, and `python -m speccheck` exit codes."""
from __future__ import annotations

import subprocess
import sys

from labkit.grading.spec_run import SpecRun
from speccheck import Finding, Report, Status

from tests.speccheck.conftest import LAUNCH_FILES

REPORT = Report('live', 'spec.yaml', 'running system', (
    Finding('node /a', Status.MET, 'running'),
    Finding('topic /scan: publisher /robot1/lidar', Status.FAILED,
            '/scan: expected publisher /robot1/lidar, found none; /robot1/lidar publishes '
            '/robot1/scan'),
    Finding('launch file', Status.NOT_CHECKED, 'OpaqueFunction <x> | y'),
))


def test_text_report_has_a_line_per_requirement_and_a_verdict():
    text = str(REPORT)
    assert text.splitlines() == [
        'speccheck live: running system against spec.yaml',
        '  met         node /a: running',
        '  FAILED      topic /scan: publisher /robot1/lidar: /scan: expected publisher '
        '/robot1/lidar, found none; /robot1/lidar publishes /robot1/scan',
        '  not checked launch file: OpaqueFunction <x> | y',
        'FAILED: 1 met, 1 failed, 1 not checked',
    ]
    assert not REPORT.ok and REPORT.exit_code == 1
    assert [f.requirement for f in REPORT.failures] == ['topic /scan: publisher /robot1/lidar']


def test_notebook_renderings_escape_and_mark_each_status():
    markdown = REPORT._repr_markdown_()
    assert '| ✗ FAILED | topic /scan: publisher /robot1/lidar |' in markdown
    assert 'OpaqueFunction <x> \\| y' in markdown
    html = REPORT._repr_html_()
    assert html.count('<tr>') == 4  # header + three findings
    assert 'OpaqueFunction &lt;x&gt; | y' in html
    assert '✓ met' in html and '? not checked' in html


def test_a_report_with_only_met_and_unchecked_lines_passes():
    report = Report('static', 's', 't', (REPORT.findings[0], REPORT.findings[2]))
    assert report.ok and report.exit_code == 0
    assert report.summary() == 'PASSED: 1 met, 0 failed, 1 not checked'


def speccheck(*words, env):
    return subprocess.run([sys.executable, '-m', 'speccheck', *words], env=env,
                          capture_output=True, text=True, timeout=120)


def test_cli_static_exit_codes(sourced, tmp_path):
    spec = LAUNCH_FILES / 'scoped.yaml'
    failing = speccheck('static', str(spec), str(LAUNCH_FILES / 'scoped.launch.py'), env=sourced)
    assert failing.returncode == 1, failing.stderr
    assert 'FAILED      topic /scan: publisher /robot1/lidar' in failing.stdout
    good = tmp_path / 'good.yaml'
    good.write_text('nodes:\n  /sensor_publisher: {}\n  /data_processor: {}\n')
    passing = speccheck('static', str(good), '--launch', 'my_robot_pkg',
                        'robot_system.launch.py', env=sourced)
    assert passing.returncode == 0, passing.stdout + passing.stderr
    assert passing.stdout.rstrip().endswith('PASSED: 5 met, 0 failed, 0 not checked')


def test_cli_bad_input_exits_2_naming_it(sourced, tmp_path):
    bad = tmp_path / 'bad.yaml'
    bad.write_text('nodes:\n  /a:\n    pakage: x\n')
    result = speccheck('static', str(bad), '--launch', 'my_robot_pkg', 'robot_system.launch.py',
                       env=sourced)
    assert (result.returncode, result.stdout) == (2, '')
    assert result.stderr.startswith(f'speccheck: error: {bad}:3: nodes./a.pakage: unknown key')
    missing = speccheck('static', str(LAUNCH_FILES / 'scoped.yaml'), '--launch', 'my_robot_pkg',
                        'nope.launch.py', env=sourced)
    assert missing.returncode == 2
    assert "file 'nope.launch.py' was not found in the share directory of package " \
           "'my_robot_pkg'" in missing.stderr
    no_target = speccheck('static', str(LAUNCH_FILES / 'scoped.yaml'), 'x:=1', env=sourced)
    assert no_target.returncode == 2 and 'static needs a launch file' in no_target.stderr


def test_cli_live_starts_checks_and_stops_the_launch(sourced, tmp_path):
    spec = tmp_path / 'live.yaml'
    spec.write_text('nodes:\n  /robot_controller:\n    parameters:\n'
                    '      robot_name: {type: string, value: my_bot}\n')
    ok = speccheck('live', str(spec), '--launch', 'my_robot_pkg', 'robot_args.launch.py',
                   'robot_name:=my_bot', '--window', '0.5', env=sourced)
    assert ok.returncode == 0, ok.stdout + ok.stderr
    assert "met         node /robot_controller: parameter robot_name: 'my_bot'" in ok.stdout
    wrong = speccheck('live', str(spec), '--launch', 'my_robot_pkg', 'robot_args.launch.py',
                      '--window', '0.5', env=sourced)
    assert wrong.returncode == 1, wrong.stdout + wrong.stderr
    assert ("FAILED      node /robot_controller: parameter robot_name: value 'scout', the spec "
            "says 'my_bot'") in wrong.stdout


def test_cli_live_reports_nodes_that_never_appear(sourced, tmp_path):
    spec = tmp_path / 'absent.yaml'
    spec.write_text('nodes:\n  /lidar: {}\n  /robot_controller: {}\n  /camera: {}\n')
    # 15 s: long enough for /robot_controller, which does start, even on a loaded machine
    result = speccheck('live', str(spec), '--launch', 'my_robot_pkg', 'robot_args.launch.py',
                       '--timeout', '15', env=sourced)
    assert result.returncode == 1, result.stdout + result.stderr
    assert 'FAILED      launch: Timed out after 15 s waiting for nodes /lidar, /camera from ' \
        in result.stdout
    # what the spec exercises' graders read from it (7.1.1 waits longer for such nodes)
    run = SpecRun('speccheck live', result.returncode, result.stdout, result.stderr)
    assert run.not_started == ['/lidar', '/camera']
