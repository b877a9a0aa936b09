"""Shared test helper of the clean-room distribution: a private ROS domain.

Domains come from the allocator described in CONTRIBUTING.md: IDs 1-89,
each guarded by `${TMPDIR:-/tmp}/ros2-textbook-domains/<id>.lock`, locked
with fcntl.flock (exclusive, non-blocking) and held for the whole session,
so parallel runs on one machine never share a domain.
"""
from __future__ import annotations

import fcntl
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

import pytest

AUTOMATIC_DOMAIN_IDS = range(1, 90)


def lease_ros_domain() -> tuple[int, int]:
    """Lock the first free domain ID; return (domain id, fd holding the lock)."""
    lock_dir = Path(os.environ.get('TMPDIR') or tempfile.gettempdir()) / 'ros2-textbook-domains'
    lock_dir.mkdir(parents=True, exist_ok=True)
    for domain_id in AUTOMATIC_DOMAIN_IDS:
        fd = os.open(lock_dir / f'{domain_id}.lock', os.O_RDWR | os.O_CREAT, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            continue
        os.ftruncate(fd, 0)
        os.write(fd, f'{os.getpid()}\n'.encode())
        return domain_id, fd
    raise RuntimeError('no free ROS domain ID in 1-89 (all locked by other runs)')


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
