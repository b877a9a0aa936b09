"""The ROS domain allocator of CONTRIBUTING.md, shared by the clean-room tests.

IDs 1-89, each guarded by `${TMPDIR:-/tmp}/ros2-textbook-domains/<id>.lock`,
locked with fcntl.flock (exclusive, non-blocking) and held while in use, so
parallel runs on one machine never share a domain.
"""
from __future__ import annotations

import fcntl
import os
import tempfile
from pathlib import Path

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
