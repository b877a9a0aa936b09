"""pytest plugin: ROS isolation for the whole test session, and no leftovers.

Each test process (every xdist worker, or the single process without
xdist) leases a ROS domain at start and exports it, so everything the tests
start inherits a private domain and localhost-only discovery.  At the end,
any process still carrying the session's lease token is killed and the
session fails, naming it.  Every session also records how long each test
took (setup, call and teardown) in build/test-times.json, which
tools/bench/ci_time.py sums by folder.  Loaded by ``python -m
textbook test`` (-p) and by tests/conftest.py.
"""
from __future__ import annotations

import json
import os
from collections import defaultdict
from pathlib import Path

import pytest

from . import paths, reaper
from .isolation import DomainLease, acquire_domain

_lease: DomainLease | None = None
#: nodeid -> seconds, collected where reports arrive (the xdist controller, or the
#: only process); written at the end of the session.
_durations: dict[str, float] = defaultdict(float)
TEST_TIMES = paths.BUILD / 'test-times.json'

#: Tier of every test below a folder (relative to the repository root).
FOLDER_TIERS = {'tests/site': 'site', 'tests/lessons': 'lesson', 'tests/exercises': 'exercise',
                'tests/snippets': 'ros', 'tests/conformance': 'ros',
                'tools/cleanroom/tests': 'ros'}
#: Fixtures that give a test ROS processes, a workspace or a launch: its tier is `ros`.
ROS_FIXTURES = {'ros_env', 'ws_install', 'session_lease', 'run_launch', 'ros_domain',
                'launch_test_session', 'cli_env', 'book_underlay', 'built_workspace'}
TIERS = ('unit', 'ros', 'lesson', 'exercise', 'site')


def _is_xdist_controller(config: pytest.Config) -> bool:
    workers = getattr(config.option, 'numprocesses', None)
    return bool(workers) and not hasattr(config, 'workerinput')


def pytest_configure(config: pytest.Config) -> None:
    global _lease
    if _lease is not None or _is_xdist_controller(config):
        return  # the controller runs no tests; its workers lease their own domains
    _lease = acquire_domain()
    os.environ.update(_lease.env())
    os.environ.pop('ROS_LOCALHOST_ONLY', None)


def tier_of(path: Path, fixtures: set[str]) -> str:
    """The tier of a test: by its folder, else `ros` if it uses a ROS fixture, else `unit`."""
    relative = path.resolve().relative_to(Path(__file__).resolve().parents[2]).as_posix()
    for folder, tier in FOLDER_TIERS.items():
        if relative.startswith(folder + '/'):
            return tier
    return 'ros' if fixtures & ROS_FIXTURES else 'unit'


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Give each test its tier marker, unless it states one itself."""
    for item in items:
        if not any(item.get_closest_marker(tier) for tier in TIERS):
            item.add_marker(tier_of(item.path, set(getattr(item, 'fixturenames', ()))))


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    _durations[report.nodeid] += report.duration


def pytest_sessionfinish(session: pytest.Session) -> None:
    if hasattr(session.config, 'workerinput') or not _durations:
        return  # a worker: its reports reach the controller, which writes the file
    TEST_TIMES.parent.mkdir(parents=True, exist_ok=True)
    TEST_TIMES.write_text(json.dumps(dict(sorted(_durations.items())), indent=0) + '\n')


def pytest_unconfigure(config: pytest.Config) -> None:
    global _lease
    if _lease is not None:
        _lease.release()
        _lease = None


def pytest_report_header(config: pytest.Config) -> str | None:
    if _lease is None:
        return 'ROS isolation: each worker leases its own ROS_DOMAIN_ID (1-89), LOCALHOST'
    return f'ROS isolation: ROS_DOMAIN_ID={_lease.domain_id}, LOCALHOST discovery'


@pytest.fixture(scope='session')
def session_lease() -> DomainLease:
    """The domain lease of this test process (its env is already in os.environ)."""
    assert _lease is not None, 'textbook.pytest_plugin did not lease a domain'
    return _lease


@pytest.fixture(scope='session', autouse=True)
def no_leftover_ros_processes():
    """Fail the session when a test left a process running (it is killed first)."""
    yield
    if _lease is None:
        return
    leftovers = reaper.reap([_lease.token], grace=3.0)
    if leftovers:
        pytest.fail('processes started by the tests were still running at the end of the '
                    'session (now killed):\n  ' + '\n  '.join(leftovers), pytrace=False)
