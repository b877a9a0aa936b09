"""The ROS domain allocator of CONTRIBUTING.md, shared by the clean-room tests.

IDs 1-89, each guarded by `${TMPDIR:-/tmp}/ros2-textbook-domains/<id>.lock`,
locked with fcntl.flock (exclusive, non-blocking) and held while in use, so
parallel runs on one machine never share a domain.  The one implementation
is launch_testing's (tools/cleanroom/src/launch_testing/domain_isolation.py).
"""
from __future__ import annotations

from launch_testing.domain_isolation import lease_free_domain


def lease_ros_domain() -> tuple[int, int]:
    """Lock the first free domain ID; return (domain id, fd holding the lock)."""
    lease = lease_free_domain()
    if lease is None:
        raise RuntimeError('no free ROS domain ID in 1-89 (all locked by other runs)')
    return lease
