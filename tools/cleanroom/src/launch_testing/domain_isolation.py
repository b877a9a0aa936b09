"""A private ROS_DOMAIN_ID for a test run whose caller did not choose one.

The ID is leased from ROS 2's own allocator, ``domain_coordinator``, through
rclhelpers.domains, which the book's tools lease through too (one allocator,
so no two runs on this machine share an ID).
"""
from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator

from rclhelpers.domains import lease_domain

__all__ = ['isolated_domain', 'lease_domain']


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
