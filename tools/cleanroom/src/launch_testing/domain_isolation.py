"""A private ROS_DOMAIN_ID for a test run whose caller did not choose one.

Uses the machine-wide allocator of this project (CONTRIBUTING.md): IDs 1-89,
each guarded by `${TMPDIR:-/tmp}/ros2-textbook-domains/<id>.lock` and held
with an exclusive fcntl.flock for as long as the run lasts, so parallel test
runs never see each other's nodes.
"""
from __future__ import annotations

import contextlib
import fcntl
import os
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

DOMAIN_IDS = range(1, 90)


def lock_dir() -> Path:
    folder = Path(os.environ.get('TMPDIR') or tempfile.gettempdir()) / 'ros2-textbook-domains'
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def lease_free_domain() -> tuple | None:
    """Lock the first free domain ID; (domain id, fd holding the lock), or None."""
    for domain_id in DOMAIN_IDS:
        fd = os.open(lock_dir() / f'{domain_id}.lock', os.O_RDWR | os.O_CREAT, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            continue
        os.ftruncate(fd, 0)
        os.write(fd, f'{os.getpid()}\n'.encode())
        return domain_id, fd
    return None


@contextlib.contextmanager
def isolated_domain(timeout: float = 60.0) -> Iterator[int | None]:
    """Set ROS_DOMAIN_ID to a leased free domain unless it is already set.

    Yields the leased domain, or None when the caller's environment already
    chose one.  Raises RuntimeError when no domain frees up within `timeout`.
    """
    if os.environ.get('ROS_DOMAIN_ID'):
        yield None
        return
    deadline = time.monotonic() + timeout
    lease = lease_free_domain()
    while lease is None:
        if time.monotonic() > deadline:
            raise RuntimeError('no free ROS_DOMAIN_ID in 1-89: every one is held by '
                               f'another test run (locks in {lock_dir()})')
        time.sleep(0.5)
        lease = lease_free_domain()
    domain_id, fd = lease
    os.environ['ROS_DOMAIN_ID'] = str(domain_id)
    try:
        yield domain_id
    finally:
        os.environ.pop('ROS_DOMAIN_ID', None)
        os.close(fd)
