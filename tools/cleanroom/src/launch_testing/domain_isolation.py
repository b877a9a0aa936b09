"""A private ROS_DOMAIN_ID for a test run whose caller did not choose one.

IDs 1-89 (CONTRIBUTING.md) come from ROS 2's own allocator,
``domain_coordinator``: a lease binds TCP port 32768 + ID, so no two live
holders on this machine share an ID and the ID comes back when the holder
releases it or dies.  The book's tools lease through the same library
(tools/textbook/isolation.py); this distribution does not import them.
"""
from __future__ import annotations

import contextlib
import itertools
import os
import time
from collections.abc import Iterator

import domain_coordinator
from domain_coordinator.impl import PORT_BASE

DOMAIN_IDS = range(1, 90)


class DomainLease:
    """One ROS domain ID held until :meth:`release` (or ``with`` exit)."""

    def __init__(self, domain_id: int, hold: contextlib.ExitStack) -> None:
        self.domain_id = domain_id
        self._hold = hold

    def release(self) -> None:
        """Give the ID back; safe to repeat."""
        self._hold.close()

    def __enter__(self) -> DomainLease:
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()


def _try_lease(ids: range) -> DomainLease | None:
    hold = contextlib.ExitStack()
    candidates = itertools.cycle(ids)
    try:
        # Left with no exception on release: an error raised while the lease
        # is held never reaches the library's generator.
        domain_id = hold.enter_context(
            domain_coordinator.domain_id(selector=lambda: next(candidates)))
    except RuntimeError:  # 'Failed to get a unique ROS domain ID'
        return None
    return DomainLease(domain_id, hold)


def lease_domain(timeout: float = 60.0, ids: range = DOMAIN_IDS) -> DomainLease:
    """Lease a free ID of ``ids``, waiting while all are held; RuntimeError after ``timeout``."""
    deadline = time.monotonic() + timeout
    while (lease := _try_lease(ids)) is None:
        if time.monotonic() >= deadline:
            raise RuntimeError(
                f'no free ROS_DOMAIN_ID in {ids.start}-{ids.stop - 1}: every one is held by '
                f'another run on this machine (domain_coordinator binds TCP port {PORT_BASE} '
                f'+ ID: ports {PORT_BASE + ids.start}-{PORT_BASE + ids.stop - 1} are all in use)')
        time.sleep(0.5)
    return lease


@contextlib.contextmanager
def isolated_domain(timeout: float = 60.0) -> Iterator[int | None]:
    """Set ROS_DOMAIN_ID to a leased free domain unless it is already set.

    Yields the leased domain, or None when the caller's environment already
    chose one.  Raises RuntimeError when no domain frees up within `timeout`.
    """
    if os.environ.get('ROS_DOMAIN_ID'):
        yield None
        return
    with lease_domain(timeout) as lease:
        os.environ['ROS_DOMAIN_ID'] = str(lease.domain_id)
        try:
            yield lease.domain_id
        finally:
            os.environ.pop('ROS_DOMAIN_ID', None)
