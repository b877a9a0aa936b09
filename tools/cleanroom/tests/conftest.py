"""Fixtures of the clean-room tests: a private ROS domain, in-process launches.

Collected only where the clean room is the `launch` in use (not over a real ROS 2).

Domains come from the allocator described in CONTRIBUTING.md (IDs 1-89 from
domain_coordinator, through launch_testing.domain_isolation), held for the
whole session, so parallel runs on one machine never share a domain.

`launch_test_session` marks every process started after it with a token in
the environment and fails the session if one survives; `run_launch` runs a
launch in this process (see _launch_run.py).  The launch/ and launch_ros/
tests use both.
"""
from __future__ import annotations

import functools
import importlib.util
import os
import uuid
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING

import pytest
from _leftovers import TOKEN_VAR, marked_processes

if TYPE_CHECKING:
    from _launch_run import LaunchResult

# These are tests of our implementation: where a real ROS 2 is sourced, `launch`
# and `ros2` are Jazzy's and the clean room is not installed (tools/setup_env.sh),
# so none of them is collected there.
_SOURCES = Path(__file__).resolve().parents[1] / 'src'
_LAUNCH = importlib.util.find_spec('launch')
CLEANROOM_IN_USE = _LAUNCH is not None and Path(_LAUNCH.origin).resolve().is_relative_to(_SOURCES)
collect_ignore_glob = [] if CLEANROOM_IN_USE else ['*']
#: the book's pytest plugin (tools/textbook), which leases each test process a domain
BOOK_PLUGIN = 'textbook.pytest_plugin'


@pytest.fixture(scope='session')
def ros_domain(request: pytest.FixtureRequest) -> Iterator[int]:
    """Lease a domain for the session and export it (with LOCALHOST discovery).

    In the book's `make test` these tests share a session with tests/, whose
    plugin has leased and exported this process's domain already: that one is
    used, because a second lease, exported, would move every later test of the
    session to another domain than the one the book's plugin guards.
    """
    if request.config.pluginmanager.has_plugin(BOOK_PLUGIN):
        yield request.getfixturevalue('session_lease').domain_id
        return
    # Imported here: the allocator is the clean room's launch_testing's, and over
    # a real ROS 2 this conftest must load without it (nothing is collected then).
    from launch_testing.domain_isolation import lease_domain
    lease = lease_domain()
    domain_id = lease.domain_id
    keys = ('ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE', 'ROS_LOCALHOST_ONLY')
    saved = {key: os.environ.get(key) for key in keys}
    os.environ.update({'ROS_DOMAIN_ID': str(domain_id),
                       'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'})
    os.environ.pop('ROS_LOCALHOST_ONLY', None)
    try:
        yield domain_id
    finally:
        for key, value in saved.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value
        lease.release()


@pytest.fixture(scope='session')
def launch_test_session(ros_domain: int,
                        tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """Private domain, private log folder, and the no-process-left-behind check.

    Sets the token and ROS_LOG_DIR in this process's environment until the
    session ends, so every process started later inherits them.  Yields the token.
    """
    token = uuid.uuid4().hex
    saved = {key: os.environ.get(key) for key in (TOKEN_VAR, 'ROS_LOG_DIR')}
    os.environ[TOKEN_VAR] = token
    os.environ['ROS_LOG_DIR'] = str(tmp_path_factory.mktemp('ros_log'))
    try:
        yield token
    finally:
        leftovers = marked_processes(token)
        for proc in leftovers:
            proc.kill()
        for key, value in saved.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value
        assert not leftovers, f'processes left behind by the tests: {leftovers}'


@pytest.fixture
def run_launch(launch_test_session: str,
               capfd: pytest.CaptureFixture) -> Callable[..., LaunchResult]:
    """`run_launch(entities, argv=(), shutdown_after=None, debug=False)` -> LaunchResult.

    Screen output is taken with capfd (so C code in this process, such as
    rclpy's logging, counts too) and written back, so a test may also read capfd
    and a failing test's report shows it.
    """
    # Imported here, as in ros_domain: _launch_run runs the clean room's launch, and
    # over a real ROS 2 this conftest must load without it.
    from _launch_run import run_in_process
    return functools.partial(run_in_process, capfd)
