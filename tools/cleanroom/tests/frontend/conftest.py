"""Fixtures of the front-end (XML / YAML) tests: write launch files, load and run them.

Launches run in this process with a LaunchService (../conftest.py's
run_launch, so a launch file's processes are marked and checked as the
launch/ and launch_ros/ tests' are), in the session's private ROS domain.
"""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from _launch_run import LaunchResult
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource

ROS2 = str(Path(sys.executable).parent / 'ros2')


@pytest.fixture(autouse=True)
def private_domain(ros_domain: int, tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """Every test in the session's private domain, logs in a temporary folder."""
    saved = os.environ.get('ROS_LOG_DIR')
    os.environ['ROS_LOG_DIR'] = str(tmp_path_factory.mktemp('ros_log'))
    yield
    if saved is None:
        os.environ.pop('ROS_LOG_DIR', None)
    else:
        os.environ['ROS_LOG_DIR'] = saved


@pytest.fixture
def write(tmp_path: Path) -> Callable[[str, str], Path]:
    """Write a (dedented) launch file below tmp_path; return its path."""
    def write_file(name: str, text: str) -> Path:
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text).lstrip())
        return path
    return write_file


@pytest.fixture
def run_file(run_launch: Callable[..., LaunchResult]) -> Callable[..., LaunchResult]:
    """Run a launch file of any format as `ros2 launch` does (arguments `name:=value`)."""
    def run(path: Path, *arguments: str) -> LaunchResult:
        return run_launch([IncludeLaunchDescription(
            AnyLaunchDescriptionSource(str(path)),
            launch_arguments=[tuple(a.split(':=', 1)) for a in arguments])], argv=arguments)
    return run


@pytest.fixture
def ros2(tmp_path: Path) -> Callable[..., subprocess.CompletedProcess]:
    """Run `ros2 ARGS...` with a package `fe_pkg` (share/fe_pkg/launch) on AMENT_PREFIX_PATH."""
    prefix = tmp_path / 'install' / 'fe_pkg'
    marker = prefix / 'share/ament_index/resource_index/packages/fe_pkg'
    marker.parent.mkdir(parents=True)
    marker.write_text('')
    (prefix / 'share/fe_pkg/launch').mkdir(parents=True)
    env = dict(os.environ, AMENT_PREFIX_PATH=str(prefix), PYTHONWARNINGS='ignore',
               RCUTILS_COLORIZED_OUTPUT='0')

    def run(*args: str, timeout: float = 60) -> subprocess.CompletedProcess:
        return subprocess.run([ROS2, *args], env=env, capture_output=True, text=True,
                              stdin=subprocess.DEVNULL, timeout=timeout, cwd=tmp_path)
    run.share = prefix / 'share/fe_pkg'  # type: ignore[attr-defined]
    return run

