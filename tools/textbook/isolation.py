"""A private ROS domain for every run, so parallel runs never see each other.

IDs 1-89 are handed out under exclusive, non-blocking ``fcntl.flock`` locks on
``${TMPDIR:-/tmp}/ros2-textbook-domains/<id>.lock`` (CONTRIBUTING.md); the lock
is held for as long as the lease lives.  Every environment built from a lease
also limits discovery to this machine and carries a unique token, which lets
the reaper find exactly the processes that this run started.

The clean room's launch_testing leases domains the same way for its own
runs (launch_testing/domain_isolation.py, also used by the clean-room tests
and benchmark); the book keeps this copy because it must run where a real
ROS 2 is installed and the clean room is not.
"""
from __future__ import annotations

import fcntl
import os
import tempfile
import time
import uuid
from pathlib import Path

DOMAIN_IDS = range(1, 90)
LEASE_VAR = 'TEXTBOOK_ROS_LEASE'
# Variables that would widen or change discovery; a run must not inherit them.
_DISCOVERY_VARS = ('ROS_LOCALHOST_ONLY', 'ROS_STATIC_PEERS', 'ROS_DISCOVERY_SERVER',
                   'FASTRTPS_DEFAULT_PROFILES_FILE', 'FASTDDS_DEFAULT_PROFILES_FILE')


def lock_dir() -> Path:
    """The shared lock folder, created on first use."""
    path = Path(os.environ.get('TMPDIR') or tempfile.gettempdir()) / 'ros2-textbook-domains'
    path.mkdir(parents=True, exist_ok=True)
    return path


class DomainLease:
    """Exclusive use of one ROS_DOMAIN_ID until :meth:`release` (or ``with`` exit)."""

    def __init__(self, domain_id: int, fd: int) -> None:
        self.domain_id = domain_id
        self.token = f'{domain_id}-{os.getpid()}-{uuid.uuid4().hex[:12]}'
        self._fd: int | None = fd

    def env(self) -> dict[str, str]:
        """The variables that put a process into this lease's private domain."""
        return {
            'ROS_DOMAIN_ID': str(self.domain_id),
            'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST',
            LEASE_VAR: self.token,
        }

    def apply(self, base: dict[str, str]) -> dict[str, str]:
        """A copy of ``base`` isolated into this domain."""
        env = {k: v for k, v in base.items() if k not in _DISCOVERY_VARS}
        env.update(self.env())
        return env

    def release(self) -> None:
        if self._fd is not None:
            os.close(self._fd)  # closing drops the flock
            self._fd = None

    def __enter__(self) -> DomainLease:
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()

    def __repr__(self) -> str:
        return f'DomainLease(domain_id={self.domain_id})'


def _try_lock(domain_id: int) -> int | None:
    fd = os.open(lock_dir() / f'{domain_id}.lock', os.O_RDWR | os.O_CREAT, 0o666)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        os.close(fd)
        return None
    os.ftruncate(fd, 0)
    os.write(fd, f'{os.getpid()}\n'.encode())  # who holds it, for humans
    return fd


def acquire_domain(timeout: float = 120.0) -> DomainLease:
    """Lease a free domain ID; waits while all 89 are taken, fails after ``timeout``."""
    deadline = time.monotonic() + timeout
    while True:
        for domain_id in DOMAIN_IDS:
            fd = _try_lock(domain_id)
            if fd is not None:
                return DomainLease(domain_id, fd)
        if time.monotonic() > deadline:
            raise RuntimeError(
                f'no free ROS domain: IDs {DOMAIN_IDS.start}-{DOMAIN_IDS.stop - 1} are all '
                f'locked in {lock_dir()} (too many runs on this machine?)')
        time.sleep(0.5)
