"""Session fixture of the clean-room tests: a private ROS domain (see ros_domains.py).

Domains come from the allocator described in CONTRIBUTING.md: IDs 1-89,
each guarded by `${TMPDIR:-/tmp}/ros2-textbook-domains/<id>.lock`, locked
with fcntl.flock (exclusive, non-blocking) and held for the whole session,
so parallel runs on one machine never share a domain.
"""
from __future__ import annotations

import os
from collections.abc import Iterator

import pytest
from ros_domains import lease_ros_domain


@pytest.fixture(scope='session')
def ros_domain() -> Iterator[int]:
    """Lease a domain for the session and export it (with LOCALHOST discovery)."""
    domain_id, fd = lease_ros_domain()
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
        os.close(fd)
