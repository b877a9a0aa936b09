"""Fixtures of the `launch` core tests.

Every test runs in a private ROS domain, with log files in a temporary
ROS_LOG_DIR; a token in the environment marks every process the tests start
(children inherit it) and the session fails if one survives.  That session
and `run_launch` are ../conftest.py's (shared with launch_ros/).
"""
from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

ROS2 = str(Path(sys.executable).parent / 'ros2')


@pytest.fixture(scope='session', autouse=True)
def _in_launch_test_session(launch_test_session: str) -> None:
    """Every test here runs in the marked session of ../conftest.py (one check for all)."""


def _write(path: Path, text: str, executable: bool = False) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    if executable:
        path.chmod(path.stat().st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
    return path


@pytest.fixture(scope='session')
def fake_prefix(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """An install prefix with package `cr_pkg` as colcon would lay it out (no build needed).

    share/cr_pkg/launch holds launch files; lib/cr_pkg holds small shell
    executables: `echo_args` prints its arguments, `exit_with CODE` exits.
    """
    prefix = tmp_path_factory.mktemp('install') / 'cr_pkg'
    _write(prefix / 'share/ament_index/resource_index/packages/cr_pkg', '')
    _write(prefix / 'share/cr_pkg/package.xml', '<package format="3"><name>cr_pkg</name>'
           '</package>\n')
    _write(prefix / 'lib/cr_pkg/echo_args', '#!/bin/sh\necho "args: $*"\n', executable=True)
    _write(prefix / 'lib/cr_pkg/exit_with', '#!/bin/sh\nexit "$1"\n', executable=True)
    _write(prefix / 'lib/cr_pkg/wait_for_signal',
           "#!/bin/sh\ntrap 'echo got INT; exit 0' INT\ntrap 'echo got TERM; exit 0' TERM\n"
           'echo ready\nwhile :; do sleep 0.05; done\n', executable=True)
    _write(prefix / 'share/cr_pkg/launch/args.launch.py', """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('speed', default_value='1.5', description='Top speed\\nin m/s'),
        DeclareLaunchArgument('mode', choices=['a', 'b']),
        DeclareLaunchArgument('name', default_value=['bot_', LaunchConfiguration('mode')]),
        LogInfo(msg=['speed=', LaunchConfiguration('speed'), ' mode=',
                     LaunchConfiguration('mode'), ' name=', LaunchConfiguration('name')]),
    ])
""")
    _write(prefix / 'share/cr_pkg/launch/procs.launch.py', """
import sys
from launch import LaunchDescription
from launch.actions import ExecuteProcess


def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['sleep', '30'], name='sleeper') for _ in range(3)
    ] + [ExecuteProcess(cmd=[sys.executable, '-c', 'print("hello", flush=True)'],
                        name='hello', output='screen')])
""")
    return prefix


@pytest.fixture
def cli_env(fake_prefix: Path) -> dict[str, str]:
    """Environment for `ros2` subprocesses: fake_prefix on AMENT_PREFIX_PATH, no colors."""
    return dict(os.environ, AMENT_PREFIX_PATH=str(fake_prefix), PYTHONWARNINGS='ignore',
                RCUTILS_COLORIZED_OUTPUT='0')


@pytest.fixture
def ros2(cli_env: dict[str, str]) -> Any:
    """Run `ros2 ARGS...` to completion; return the CompletedProcess (text)."""
    def run(*args: str, timeout: float = 30, **kwargs: Any) -> subprocess.CompletedProcess:
        return subprocess.run([ROS2, *args], env=cli_env, capture_output=True, text=True,
                              stdin=subprocess.DEVNULL, timeout=timeout, **kwargs)
    return run
