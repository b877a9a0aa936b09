"""A private ROS domain for every run, so parallel runs never see each other.

IDs 1-89 come from ROS 2's own allocator, ``domain_coordinator`` (the
package ament_cmake_ros's isolated tests use): a lease binds TCP port
32768 + ID, so the kernel itself guarantees that no two live holders on this
machine get the same ID and frees it when the holder closes it or dies.  The
lease is held for as long as this object lives.  Every environment built from a
lease also limits discovery to this machine and carries a unique token, which
lets the reaper find exactly the processes that this run started.

The clean room's launch_testing (launch_testing/domain_isolation.py) leases
through the same library; neither side imports the other (ARCHITECTURE.md).
"""
from __future__ import annotations

import contextlib
import itertools
import os
import time
import uuid

try:
    import domain_coordinator
    from domain_coordinator.impl import PORT_BASE
except ImportError as missing:  # a real ROS 2 install without the package
    raise ImportError("the book isolates every run with ROS 2's domain_coordinator: "
                      'sudo apt install ros-jazzy-domain-coordinator (README)') from missing

DOMAIN_IDS = range(1, 90)
LEASE_VAR = 'TEXTBOOK_ROS_LEASE'
# Variables that would widen or change discovery; a run must not inherit them.
_DISCOVERY_VARS = ('ROS_LOCALHOST_ONLY', 'ROS_STATIC_PEERS', 'ROS_DISCOVERY_SERVER',
                   'FASTRTPS_DEFAULT_PROFILES_FILE', 'FASTDDS_DEFAULT_PROFILES_FILE')


class DomainLease:
    """Exclusive use of one ROS_DOMAIN_ID until :meth:`release` (or ``with`` exit)."""

    def __init__(self, domain_id: int, hold: contextlib.ExitStack) -> None:
        self.domain_id = domain_id
        self.token = f'{domain_id}-{os.getpid()}-{uuid.uuid4().hex[:12]}'
        self._hold = hold

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
        """Give the ID back (closes domain_coordinator's socket); safe to repeat."""
        self._hold.close()

    def __enter__(self) -> DomainLease:
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()

    def __repr__(self) -> str:
        return f'DomainLease(domain_id={self.domain_id})'


def _try_lease(ids: range) -> DomainLease | None:
    """One pass of domain_coordinator over ``ids``; None when every one is held."""
    hold = contextlib.ExitStack()
    candidates = itertools.cycle(ids)
    try:
        # Entered by the stack and left with no exception on release: an error
        # raised while the lease is held never reaches the library's generator.
        domain_id = hold.enter_context(
            domain_coordinator.domain_id(selector=lambda: next(candidates)))
    except RuntimeError:  # 'Failed to get a unique ROS domain ID'
        return None
    return DomainLease(domain_id, hold)


def acquire_domain(timeout: float = 120.0, ids: range = DOMAIN_IDS) -> DomainLease:
    """Lease a free domain ID of ``ids``; waits while all are taken, fails after ``timeout``."""
    deadline = time.monotonic() + timeout
    while (lease := _try_lease(ids)) is None:
        if time.monotonic() >= deadline:
            raise RuntimeError(
                f'no free ROS domain: IDs {ids.start}-{ids.stop - 1} are all held by other '
                f'runs on this machine (domain_coordinator binds TCP port {PORT_BASE} + ID: '
                f'ports {PORT_BASE + ids.start}-{PORT_BASE + ids.stop - 1} are all in use; '
                f'too many runs at once?)')
        time.sleep(0.5)
    return lease
