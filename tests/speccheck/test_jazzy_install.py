"""speccheck installs and runs next to a real ROS 2 Jazzy, without the book (issue 24).

The Jazzy is SPECCHECK_JAZZY (a setup.bash, e.g. /opt/ros/jazzy/setup.bash) or
else the run-only reference in ../shared/jazzy-reference, installed into
build/jazzy-reference as `python -m textbook parity` installs it (CI has it).
A fresh venv over the sourced Jazzy gets `pip install ./tools/speccheck`
(which brings tools/rclhelpers) and nothing else of this repository; the
Jazzy's own colcon builds my_robot_pkg into a workspace of the test's; the
installed `speccheck` then checks a lesson's spec statically and running, in
this test process's ROS domain.
"""
from __future__ import annotations

import os
import shlex
import subprocess
from collections.abc import Callable
from pathlib import Path

import pytest
from textbook import parity

ROOT = Path(__file__).parents[2]
SPEC = 'my_robot_pkg/specs/patrol.spec.yaml'

pytestmark = pytest.mark.skipif(
    not os.environ.get('SPECCHECK_JAZZY') and not parity.REFERENCE_INSTALLER.exists(),
    reason='no ROS 2 Jazzy: set SPECCHECK_JAZZY to its setup.bash, or put the reference '
           f'at {parity.REFERENCE_INSTALLER.parent}')


@pytest.fixture(scope='module')
def in_jazzy(tmp_path_factory, session_lease) -> Callable[..., subprocess.CompletedProcess[str]]:
    """`in_jazzy(command, timeout)`: `command` in a bash with the Jazzy and a workspace
    of my_robot_pkg (built by the Jazzy's colcon) sourced, in this process's ROS
    domain (`session_lease`, in os.environ), from snippets/."""
    setup = parity.reference_setup(os.environ.get('SPECCHECK_JAZZY'))
    env = parity.without_the_book(os.environ)
    env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    workspace = tmp_path_factory.mktemp('jazzy_ws')
    sourced = f'source {shlex.quote(str(setup))}'

    def run(command: str, timeout: float, cwd: Path = ROOT / 'snippets',
            workspace_sourced: bool = True) -> subprocess.CompletedProcess[str]:
        script = sourced
        if workspace_sourced:
            script += f' && source {shlex.quote(str(workspace / "install/setup.bash"))}'
        return subprocess.run(['bash', '-c', f'{script} && {command}'], cwd=cwd, env=env,
                              capture_output=True, text=True, timeout=timeout)

    built = run(f'colcon build --base-paths {shlex.quote(str(ROOT / "snippets/my_robot_pkg"))}',
                timeout=600, cwd=workspace, workspace_sourced=False)
    assert built.returncode == 0, built.stdout + built.stderr
    return run


@pytest.fixture(scope='module')
def speccheck(in_jazzy, tmp_path_factory) -> str:
    """The `speccheck` command of a venv made over the sourced Jazzy."""
    venv = tmp_path_factory.mktemp('jazzy') / 'venv'
    made = in_jazzy(f'python3 -m venv --system-site-packages {venv} && '
                    f'{venv}/bin/pip install -q {ROOT}/tools/speccheck', timeout=600)
    assert made.returncode == 0, made.stdout + made.stderr
    return str(venv / 'bin' / 'speccheck')


def test_the_installed_speccheck_imports_nothing_of_the_book(in_jazzy, speccheck):
    python = Path(speccheck).with_name('python')
    code = ('import sys, speccheck.__main__, speccheck.launcher, speccheck.snapshot\n'
            "book = {'labkit', 'textbook', 'ros2_cleanroom'}\n"
            "print(sorted(book & {name.split('.')[0] for name in sys.modules}))")
    probe = in_jazzy(f'{python} -c {shlex.quote(code)}', timeout=120)
    assert probe.returncode == 0, probe.stderr
    assert probe.stdout.strip() == '[]'


def test_static_then_live_on_jazzy(in_jazzy, speccheck):
    static = in_jazzy(f'{speccheck} static {SPEC} --launch my_robot_pkg patrol.launch.py',
                      timeout=180)
    assert static.returncode == 0, static.stdout + static.stderr
    assert 'PASSED: 20 met, 0 failed' in static.stdout
    live = in_jazzy(f'{speccheck} live {SPEC} --launch my_robot_pkg patrol.launch.py',
                    timeout=180)
    assert live.returncode == 0, live.stdout + live.stderr
    assert 'met         topic /scout/distance: rate 4..6 Hz: measured' in live.stdout
    assert 'FAILED' not in live.stdout


def test_live_names_the_node_that_never_came_on_jazzy(in_jazzy, speccheck, tmp_path):
    spec = tmp_path / 'absent.yaml'
    spec.write_text('nodes:\n  /scout/robot_controller: {}\n  /scout/lidar: {}\n')
    live = in_jazzy(f'{speccheck} live {spec} --launch my_robot_pkg patrol.launch.py '
                    '--timeout 10', timeout=180)
    assert live.returncode == 1, live.stdout + live.stderr
    assert 'FAILED      launch: Timed out after 10 s waiting for node /scout/lidar from ' \
        '`ros2 launch my_robot_pkg patrol.launch.py`.' in live.stdout
