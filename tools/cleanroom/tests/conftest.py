"""Session fixture of the clean-room tests: a private ROS domain.

Collected only where the clean room is the `launch` in use (not over a real ROS 2).

Domains come from the allocator described in CONTRIBUTING.md (IDs 1-89 from
domain_coordinator, through launch_testing.domain_isolation), held for the
whole session, so parallel runs on one machine never share a domain.
"""
from __future__ import annotations

import importlib.util
import os
from collections.abc import Iterator
from pathlib import Path

import pytest

# These are tests of our implementation: where a real ROS 2 is sourced, `launch`
# and `ros2` are Jazzy's and the clean room is not installed (tools/setup_env.sh),
# so none of them is collected there.
_SOURCES = Path(__file__).resolve().parents[1] / 'src'
_LAUNCH = importlib.util.find_spec('launch')
CLEANROOM_IN_USE = _LAUNCH is not None and Path(_LAUNCH.origin).resolve().is_relative_to(_SOURCES)
collect_ignore_glob = [] if CLEANROOM_IN_USE else ['*']


@pytest.fixture(scope='session')
def ros_domain() -> Iterator[int]:
    """Lease a domain for the session and export it (with LOCALHOST discovery)."""
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
