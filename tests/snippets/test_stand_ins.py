"""Interface packages build from the ROS 2 wheels, and the headless turtlesim
never shadows a real one: neither the book's workspace build nor a student's
plain ``colcon build`` installs it where the environment has a turtlesim."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from textbook import paths, workspace

INDEX = 'share/ament_index/resource_index/packages'


def fake_prefix(root: Path, package: str, headless: bool = False) -> Path:
    """An install prefix whose ament index lists ``package``."""
    (root / INDEX).mkdir(parents=True)
    (root / INDEX / package).write_text('')
    if headless:
        (root / 'share' / package).mkdir(parents=True)
        (root / 'share' / package / 'HEADLESS').write_text('')
    return root


def test_a_real_turtlesim_is_found_and_our_headless_build_is_not(tmp_path):
    real = fake_prefix(tmp_path / 'opt_ros', 'turtlesim')
    ours = fake_prefix(tmp_path / 'ws_install', 'turtlesim', headless=True)
    assert workspace.installed_for_real('turtlesim', {'AMENT_PREFIX_PATH': str(ours)}) is None
    env = {'AMENT_PREFIX_PATH': f'{ours}{os.pathsep}{real}'}
    assert workspace.installed_for_real('turtlesim', env) == str(real)
    assert workspace.skipped_packages(env) == ['turtlesim']
    assert workspace.skipped_packages({}) == []


def test_the_book_build_skips_turtlesim_where_a_real_one_is_installed(tmp_path, monkeypatch):
    real = fake_prefix(tmp_path / 'opt_ros', 'turtlesim')
    monkeypatch.setenv('AMENT_PREFIX_PATH', str(real))
    command = workspace.colcon_command()
    assert command[-2:] == ['--packages-skip', 'turtlesim']
    monkeypatch.delenv('AMENT_PREFIX_PATH')
    assert '--packages-skip' not in workspace.colcon_command()


def test_a_plain_colcon_build_installs_nothing_over_a_real_turtlesim(tmp_path):
    real = fake_prefix(tmp_path / 'opt_ros', 'turtlesim')
    (tmp_path / 'ws/src').mkdir(parents=True)
    (tmp_path / 'ws/src/turtlesim').symlink_to(paths.SNIPPETS / 'turtlesim')
    env = dict(os.environ, AMENT_PREFIX_PATH=str(real),
               PATH=paths.tool_path())
    result = subprocess.run([paths.executable('colcon'), 'build'], cwd=tmp_path / 'ws',
                            env=env, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    install = tmp_path / 'ws/install/turtlesim'
    assert not (install / INDEX / 'turtlesim').exists(), 'would shadow the real turtlesim'
    assert not (install / 'lib/turtlesim/turtlesim_node').exists()
    log = (tmp_path / 'ws/log/latest_build/turtlesim/stdout.log').read_text()
    assert f'turtlesim is installed in {real}; the headless turtlesim is not built' in log


def test_generated_messages_import_after_sourcing_the_workspace(ros_env, ws_install):
    if 'turtlesim' in workspace.skipped_packages():
        pytest.skip('a real turtlesim is installed; the headless one is not built')
    probe = ("from ament_index_python.packages import get_package_prefix\n"
             "from turtlesim.msg import Pose\n"
             "from turtlesim.srv import Spawn\n"
             "from turtlesim.action import RotateAbsolute\n"
             "from rclpy.serialization import serialize_message, deserialize_message\n"
             "pose = deserialize_message(serialize_message(Pose(x=1.5)), Pose)\n"
             "print(get_package_prefix('turtlesim'), pose.x, Spawn.Request().name == '',\n"
             "      RotateAbsolute.Goal().theta)\n")
    result = subprocess.run([sys.executable, '-c', probe], env=ros_env,
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == [str(ws_install / 'turtlesim'), '1.5', 'True', '0.0']
