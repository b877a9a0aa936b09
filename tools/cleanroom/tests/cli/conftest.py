"""Fixtures of the `ros2 node|topic|param` tests.

Each test module gets its own ROS domain (same allocator as
../conftest.py, CONTRIBUTING.md), so the graph a module lists holds exactly
the sample nodes it started, even if an earlier module's nodes are still
being forgotten by discovery.  Every process started here runs in its own
session and is stopped (SIGINT, then SIGKILL) when the module ends.
"""
from __future__ import annotations

import os
import signal
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import psutil
import pytest
from _polling import wait_for
from cli_processes import stop_process
from launch_testing.domain_isolation import lease_domain

ROS2 = str(Path(sys.executable).parent / 'ros2')
SAMPLE_NODES = str(Path(__file__).with_name('sample_nodes.py'))


def _sigint_as_in_a_terminal() -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)


@pytest.fixture(scope='module')
def cli_env(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, str]]:
    """Environment for the commands and nodes of one test module: a private domain."""
    lease = lease_domain()
    domain_id = lease.domain_id
    env = {k: v for k, v in os.environ.items()
           if k not in ('ROS_LOCALHOST_ONLY', 'ROS_STATIC_PEERS')}
    env.update(ROS_DOMAIN_ID=str(domain_id), ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST',
               PYTHONUNBUFFERED='1', RCUTILS_COLORIZED_OUTPUT='0',
               ROS_LOG_DIR=str(tmp_path_factory.mktemp('ros_log')))
    try:
        yield env
    finally:  # the daemon the module's first listing started, as a user would stop it
        subprocess.run([ROS2, 'daemon', 'stop'], env=env, capture_output=True, check=False)
        lease.release()


def _wait_for_the_daemon_listing(args: tuple[str, ...], expected: list[str],
                                env: dict[str, str], timeout: float = 15.0) -> None:
    """Wait until the running daemon's `ros2 ARGS` output holds every `expected` line,
    as a user re-runs a listing until what they just started shows up (the daemon
    answers with what discovery has brought it so far: nodes before their topics)."""
    def lists_every_line() -> bool:
        listed = subprocess.run([ROS2, *args], env=env, capture_output=True, text=True,
                                check=False).stdout.splitlines()
        return all(line in listed for line in expected)
    wait_for(lists_every_line, timeout, f'the ros2 daemon to list {expected}')


def _wait_for_the_daemon(node: str, env: dict[str, str]) -> None:
    """With a daemon running, wait until it lists `node`."""
    status = subprocess.run([ROS2, 'daemon', 'status'], env=env, capture_output=True,
                            text=True, check=False)
    if status.stdout.strip() == 'The daemon is running':
        _wait_for_the_daemon_listing(('node', 'list', '-a'), [node], env)


@pytest.fixture(scope='module')
def daemon_listing(cli_env: dict[str, str]) -> Callable[..., None]:
    """`daemon_listing(('topic', 'list'), ['/chatter'])`: start the module's daemon and
    wait until that listing shows every expected line."""
    def wait(args: tuple[str, ...], expected: list[str]) -> None:
        subprocess.run([ROS2, 'daemon', 'start'], env=cli_env, capture_output=True,
                       check=True)
        _wait_for_the_daemon_listing(args, expected, cli_env)
    return wait


@pytest.fixture(scope='module')
def start_node(cli_env: dict[str, str]) -> Iterator[Callable[..., subprocess.Popen]]:
    """`start_node('talker', '--ros-args', ...)`: a sample node, up when this returns."""
    started: list[subprocess.Popen] = []

    def start(kind: str, *ros_args: str) -> subprocess.Popen:
        proc = subprocess.Popen([sys.executable, SAMPLE_NODES, kind, *ros_args], env=cli_env,
                                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                start_new_session=True)
        started.append(proc)
        ready, _, name = proc.stdout.readline().strip().partition(' ')
        assert ready == 'ready', f'sample node {kind} did not start'
        _wait_for_the_daemon(name, cli_env)
        return proc

    try:
        yield start
    finally:
        for proc in started:
            stop_process(proc)
        for proc in started:
            assert not psutil.pid_exists(proc.pid) or \
                psutil.Process(proc.pid).status() == psutil.STATUS_ZOMBIE


@pytest.fixture(scope='module')
def ros2(cli_env: dict[str, str]) -> Callable[..., subprocess.CompletedProcess]:
    """Run `ros2 ARGS...` in the module's domain and return its result (text).

    `env` adds variables for this one command (e.g. PYTHONWARNINGS).
    """
    def run(*args: str, timeout: float = 30.0,
            env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
        return subprocess.run([ROS2, *args], env={**cli_env, **(env or {})},
                              capture_output=True, text=True, timeout=timeout)
    return run


@pytest.fixture
def ros2_background(cli_env: dict[str, str]) -> Iterator[Callable[..., subprocess.Popen]]:
    """Start `ros2 ARGS...` streaming (echo, hz) in its own session; stopped after the test."""
    started: list[subprocess.Popen] = []

    def start(*args: str) -> subprocess.Popen:
        # Ctrl+C as in a terminal: a test run started in the background (nohup ... &,
        # a CI script) hands its children SIGINT ignored, and Python then never raises
        # KeyboardInterrupt in them
        proc = subprocess.Popen([ROS2, *args], env=cli_env, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, start_new_session=True,
                                preexec_fn=_sigint_as_in_a_terminal)
        started.append(proc)
        return proc

    try:
        yield start
    finally:
        for proc in started:
            stop_process(proc)
