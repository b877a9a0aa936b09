"""A private ROS_DOMAIN_ID for a run, from ROS 2's own allocator.

IDs 1-89 (CONTRIBUTING.md) come from ``domain_coordinator``, the package
ament_cmake_ros's isolated tests use: a lease binds TCP port 32768 + ID, so
the kernel itself guarantees that no two live holders on this machine share
an ID, and frees it when the holder releases it or dies.  The book's tools
(textbook.isolation) and the clean room's launch_test
(launch_testing.domain_isolation) both lease here.  A module of its own, not
imported by ``rclhelpers``: labkit needs rclhelpers but not this library.
"""
from __future__ import annotations

import contextlib
import itertools
import random
import time
from collections.abc import Callable
from typing import TypeVar

import domain_coordinator
from domain_coordinator.impl import PORT_BASE

DOMAIN_IDS = range(1, 90)


class DomainLease:
    """Exclusive use of one ROS_DOMAIN_ID until :meth:`release` (or ``with`` exit)."""

    def __init__(self, domain_id: int, hold: contextlib.ExitStack) -> None:
        self.domain_id = domain_id
        self._hold = hold

    def release(self) -> None:
        """Give the ID back (closes domain_coordinator's socket); safe to repeat."""
        self._hold.close()

    def __enter__(self):  # the subclass's type, for `with lease_domain(...) as lease`
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()

    def __repr__(self) -> str:
        return f'{type(self).__name__}(domain_id={self.domain_id})'


Lease = TypeVar('Lease', bound=DomainLease)


def _try_lease(ids: range, make: Callable[[int, contextlib.ExitStack], Lease]) -> Lease | None:
    """One pass of domain_coordinator over ``ids``; None when every one is held."""
    hold = contextlib.ExitStack()
    # From a random place in the range, not from its start: an ID another run
    # has just given back may still carry that run's nodes (a killed node stays
    # discovered until its DDS lease ends), and the lowest free ID would be
    # exactly that one.
    start = random.randrange(len(ids))
    candidates = itertools.cycle([*ids[start:], *ids[:start]])
    try:
        # Entered by the stack and left with no exception on release: an error
        # raised while the lease is held never reaches the library's generator.
        domain_id = hold.enter_context(
            domain_coordinator.domain_id(selector=lambda: next(candidates)))
    except RuntimeError:  # 'Failed to get a unique ROS domain ID'
        return None
    return make(domain_id, hold)


def lease_domain(timeout: float = 60.0, ids: range = DOMAIN_IDS,
                 make: Callable[[int, contextlib.ExitStack], Lease] = DomainLease) -> Lease:
    """Lease a free ID of ``ids``, waiting while all are held; RuntimeError after ``timeout``.

    ``make`` builds the lease object (a :class:`DomainLease` subclass may add
    what its caller needs, such as an environment).
    """
    deadline = time.monotonic() + timeout
    while (lease := _try_lease(ids, make)) is None:
        if time.monotonic() >= deadline:
            raise RuntimeError(
                f'no free ROS domain: IDs {ids.start}-{ids.stop - 1} are all held by other '
                f'runs on this machine (domain_coordinator binds TCP port {PORT_BASE} + ID: '
                f'ports {PORT_BASE + ids.start}-{PORT_BASE + ids.stop - 1} are all in use; '
                'too many runs at once?)')
        time.sleep(0.5)
    return lease
