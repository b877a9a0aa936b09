"""speccheck installs and runs next to a real ROS 2 Jazzy, without the book (issue 24).

Runs when SPECCHECK_JAZZY names a Jazzy's setup.bash (the reference:
`SPECCHECK_JAZZY=build/jazzy-reference/setup.bash`); the snippets workspace
built for that Jazzy is `build/jazzy/ws/install` (what `python -m textbook parity`
builds), or SPECCHECK_JAZZY_WS.  A fresh venv over the sourced Jazzy gets
`pip install tools/rclhelpers tools/speccheck` and nothing else of this
repository; its `speccheck` then checks a lesson's spec statically and running,
in this test process's ROS domain.  Without SPECCHECK_JAZZY it is skipped (and
says so): the clean-room environment has no second ROS 2 to install next to.
"""
from __future__ import annotations

import os
import shlex
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[2]
JAZZY = os.environ.get('SPECCHECK_JAZZY')
WORKSPACE = Path(os.environ.get('SPECCHECK_JAZZY_WS', ROOT / 'build/jazzy/ws/install'))
SPEC = 'my_robot_pkg/specs/patrol.spec.yaml'

pytestmark = pytest.mark.skipif(not JAZZY, reason='SPECCHECK_JAZZY (a Jazzy setup.bash) not set')


def in_jazzy(command: str, timeout: float) -> subprocess.CompletedProcess[str]:
    """`command` in a bash with the Jazzy and the workspace sourced, in this
    process's ROS domain, from snippets/."""
    script = (f'source {shlex.quote(str(ROOT / JAZZY))} && '
              f'source {shlex.quote(str(WORKSPACE / "setup.bash"))} && {command}')
    env = {name: value for name, value in os.environ.items()
           if not name.startswith(('PYTHON', 'AMENT', 'COLCON', 'VIRTUAL_ENV'))}
    env['PATH'] = os.pathsep.join(entry for entry in env.get('PATH', os.defpath).split(os.pathsep)
                                  if not entry.startswith(str(ROOT)))  # not the book's venv
    env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    return subprocess.run(['bash', '-c', script], cwd=ROOT / 'snippets', env=env,
                          capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope='module')
def speccheck(tmp_path_factory) -> str:
    """The `speccheck` command of a venv made over the sourced Jazzy."""
    venv = tmp_path_factory.mktemp('jazzy') / 'venv'
    made = in_jazzy(f'python3 -m venv --system-site-packages {venv} && '
                    f'{venv}/bin/pip install -q {ROOT}/tools/rclhelpers {ROOT}/tools/speccheck',
                    timeout=600)
    assert made.returncode == 0, made.stdout + made.stderr
    return str(venv / 'bin' / 'speccheck')


def test_the_installed_speccheck_imports_nothing_of_the_book(speccheck):
    python = Path(speccheck).with_name('python')
    code = ('import sys, speccheck.__main__, speccheck.launcher, speccheck.snapshot\n'
            "book = {'labkit', 'textbook', 'ros2_cleanroom'}\n"
            "print(sorted(book & {name.split('.')[0] for name in sys.modules}))")
    probe = in_jazzy(f'{python} -c {shlex.quote(code)}', timeout=120)
    assert probe.returncode == 0, probe.stderr
    assert probe.stdout.strip() == '[]'


def test_static_then_live_on_jazzy(speccheck):
    static = in_jazzy(f'{speccheck} static {SPEC} --launch my_robot_pkg patrol.launch.py',
                      timeout=180)
    assert static.returncode == 0, static.stdout + static.stderr
    assert 'PASSED: 20 met, 0 failed' in static.stdout
    live = in_jazzy(f'{speccheck} live {SPEC} --launch my_robot_pkg patrol.launch.py',
                    timeout=180)
    assert live.returncode == 0, live.stdout + live.stderr
    assert 'met         topic /scout/distance: rate 4..6 Hz: measured' in live.stdout
    assert 'FAILED' not in live.stdout


def test_live_names_the_node_that_never_came_on_jazzy(speccheck, tmp_path):
    spec = tmp_path / 'absent.yaml'
    spec.write_text('nodes:\n  /scout/robot_controller: {}\n  /scout/lidar: {}\n')
    live = in_jazzy(f'{speccheck} live {spec} --launch my_robot_pkg patrol.launch.py '
                    '--timeout 10', timeout=180)
    assert live.returncode == 1, live.stdout + live.stderr
    assert 'FAILED      launch: Timed out after 10 s waiting for node /scout/lidar from ' \
        '`ros2 launch my_robot_pkg patrol.launch.py`.' in live.stdout
