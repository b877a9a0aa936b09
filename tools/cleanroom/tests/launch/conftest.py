"""Fixtures of the `launch` core tests.

Every test runs in a private ROS domain (see ../conftest.py), with log files
in a temporary ROS_LOG_DIR.  A token in the environment marks every process
the tests start (children inherit it); the session fails if one survives.
"""
from __future__ import annotations

import os
import stat
import subprocess
import sys
import uuid
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import psutil
import pytest

TOKEN_VAR = 'CLEANROOM_LAUNCH_TEST_TOKEN'
ROS2 = str(Path(sys.executable).parent / 'ros2')


def _marked_processes(token: str) -> list[psutil.Process]:
    found = []
    for proc in psutil.process_iter():
        if proc.pid == os.getpid():
            continue
        try:
            if proc.environ().get(TOKEN_VAR) == token and \
                    proc.status() != psutil.STATUS_ZOMBIE:  # zombies are dead already
                found.append(proc)
        except (psutil.AccessDenied, psutil.NoSuchProcess, psutil.ZombieProcess):
            continue
    return found


@pytest.fixture(scope='session', autouse=True)
def launch_test_session(ros_domain: int,
                        tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """Private domain, private log folder, and the no-process-left-behind check."""
    token = uuid.uuid4().hex
    saved = {key: os.environ.get(key) for key in (TOKEN_VAR, 'ROS_LOG_DIR')}
    os.environ[TOKEN_VAR] = token
    os.environ['ROS_LOG_DIR'] = str(tmp_path_factory.mktemp('ros_log'))
    try:
        yield token
    finally:
        leftovers = _marked_processes(token)
        for proc in leftovers:
            proc.kill()
        for key, value in saved.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value
        assert not leftovers, f'processes left behind by the tests: {leftovers}'


class LaunchResult:
    """Exit code, started processes and screen output of one in-process launch."""

    def __init__(self, returncode: int, started: list[dict[str, Any]], output: str) -> None:
        self.returncode = returncode
        self.started = started
        self.output = output

    @property
    def names(self) -> list[str]:
        """Process names, sorted by their number N (processes start concurrently)."""
        return sorted((p['name'] for p in self.started),
                      key=lambda name: int(name.rsplit('-', 1)[1]))

    def process(self, name: str) -> dict[str, Any]:
        """The (first) started process called `name`."""
        return next(p for p in self.started if p['name'] == name)

    def user_lines(self) -> list[str]:
        """The messages LogInfo printed."""
        prefix = '[INFO] [launch.user]: '
        return [line[len(prefix):] for line in self.output.splitlines()
                if line.startswith(prefix)]


@pytest.fixture
def run_launch(capsys: pytest.CaptureFixture) -> Any:
    """Run entities in a LaunchService in this process and return a LaunchResult.

    The launch ends when idle, or `shutdown_after` seconds after it started.
    Processes it started must be gone when run() returns.
    """
    from launch import LaunchDescription, LaunchService
    from launch.actions import RegisterEventHandler, Shutdown, TimerAction
    from launch.event_handlers import OnProcessStart

    def run(entities: list, *, argv: tuple = (), shutdown_after: float | None = None,
            debug: bool = False) -> LaunchResult:
        started: list[dict[str, Any]] = []

        def on_start(event: Any, context: Any) -> None:
            started.append({'name': event.process_name, 'pid': event.pid,
                            'cmd': list(event.cmd), 'env': dict(event.env or {}),
                            'cwd': event.cwd})

        extra = [] if shutdown_after is None else [
            TimerAction(period=shutdown_after, actions=[Shutdown(reason='test done')])]
        capsys.readouterr()
        service = LaunchService(argv=list(argv), debug=debug)
        service.include_launch_description(LaunchDescription(
            [RegisterEventHandler(OnProcessStart(on_start=on_start)), *entities, *extra]))
        returncode = service.run()
        output = capsys.readouterr().out
        for proc in started:
            assert not psutil.pid_exists(proc['pid']) or \
                psutil.Process(proc['pid']).status() == psutil.STATUS_ZOMBIE, proc
        return LaunchResult(returncode, started, output)

    return run


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
