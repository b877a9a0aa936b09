"""A private ROS domain for every run, so parallel runs never see each other.

The ID is leased from ROS 2's own allocator, ``domain_coordinator``, through
rclhelpers.domains (which the clean room's launch_test shares): the lease is
held for as long as this object lives.  Every environment built from a lease
also limits discovery to this machine and carries a unique token, which lets
the reaper find exactly the processes that this run started.  Where the ROS 2
stack is the PyPI wheels, it also preloads tools/ddsfix's shim, without which
a node can hang for ever at shutdown (tools/ddsfix/forever_wait.c says why).
"""
from __future__ import annotations

import contextlib
import os
import subprocess
import sys
import uuid
from collections.abc import Iterable, Iterator
from pathlib import Path

from . import paths

try:
    from rclhelpers import domains
except ImportError as missing:  # a real ROS 2 install without the package
    if missing.name != 'domain_coordinator':
        raise
    raise ImportError("the book isolates every run with ROS 2's domain_coordinator: "
                      'sudo apt install ros-jazzy-domain-coordinator (README)') from missing

DOMAIN_IDS = domains.DOMAIN_IDS
LEASE_VAR = 'TEXTBOOK_ROS_LEASE'
# Variables that would widen or change discovery; a run must not inherit them.
_DISCOVERY_VARS = ('ROS_LOCALHOST_ONLY', 'ROS_STATIC_PEERS', 'ROS_DISCOVERY_SERVER',
                   'FASTRTPS_DEFAULT_PROFILES_FILE', 'FASTDDS_DEFAULT_PROFILES_FILE')

#: The shim tools/setup_env.sh builds into a venv of the wheels (never into one
#: under a real ROS 2, whose Fast DDS needs none): where it is missing, nothing
#: is preloaded.
DDSFIX = Path(sys.prefix) / 'lib' / 'ddsfix' / 'libforever_wait.so'


def preload_ddsfix(preload: str) -> str:
    """``preload`` (an LD_PRELOAD value) with the shim added if it was built, dropped if not."""
    entries = [entry for entry in preload.replace(':', ' ').split()
               if Path(entry).name != DDSFIX.name]
    if DDSFIX.is_file():
        entries.append(str(DDSFIX))
    return ' '.join(entries)


class DomainLease(domains.DomainLease):
    """A leased ROS_DOMAIN_ID, with the environment and token of a run inside it."""

    def __init__(self, domain_id: int, hold: contextlib.ExitStack) -> None:
        super().__init__(domain_id, hold)
        self.token = f'{domain_id}-{os.getpid()}-{uuid.uuid4().hex[:12]}'

    def env(self, base: dict[str, str] | None = None) -> dict[str, str]:
        """The variables that put a process into this lease's private domain (and
        LD_PRELOAD: ``base``'s, default os.environ's, with the shim where built)."""
        preload = preload_ddsfix((os.environ if base is None else base).get('LD_PRELOAD', ''))
        return {
            'ROS_DOMAIN_ID': str(self.domain_id),
            'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST',
            LEASE_VAR: self.token,
            **({'LD_PRELOAD': preload} if preload else {}),
        }

    def apply(self, base: dict[str, str]) -> dict[str, str]:
        """A copy of ``base`` isolated into this domain."""
        env = {k: v for k, v in base.items() if k not in (*_DISCOVERY_VARS, 'LD_PRELOAD')}
        env.update(self.env(base))
        return env


def acquire_domain(timeout: float = 120.0, ids: range = DOMAIN_IDS) -> DomainLease:
    """Lease a free domain ID of ``ids``; waits while all are taken, fails after ``timeout``."""
    return domains.lease_domain(timeout, ids, make=DomainLease)


@contextlib.contextmanager
def holding_fixed_domains(ids: Iterable[int], timeout: float = 1200.0) -> Iterator[None]:
    """Exclusive use of the domain IDs a system uses by a fixed number while it runs.

    Lesson 6.7's broken system puts a sensor in domain 101 on purpose; two runs
    at once would each see the other's sensor there.  The same allocator leases
    these IDs, so a second run waits until the first is done (``timeout``
    only stops a run that never ends).
    """
    with contextlib.ExitStack() as held:
        for domain_id in sorted(set(ids)):
            held.enter_context(domains.lease_domain(timeout, range(domain_id, domain_id + 1)))
            held.callback(stop_daemon, domain_id)  # runs first: before the lease goes
        yield


def stop_daemon(domain_id: int) -> None:
    """Stop this stack's `ros2` daemon of ``domain_id``, if one runs.

    A daemon outlives the run that started it (Jazzy's `ros2` leaves it on
    purpose).  In a fixed domain the next holder may be the other stack (the
    parity command runs 6.7 on both), whose `ros2` would then talk to a daemon
    it cannot understand on the same port (11511 + ID): Jazzy's client got
    `ConnectionResetError`, and `ros2 node list` printed nothing."""
    try:
        ros2 = paths.executable('ros2')
    except FileNotFoundError:
        return
    subprocess.run([ros2, 'daemon', 'stop'], env={**os.environ, 'ROS_DOMAIN_ID': str(domain_id)},
                   capture_output=True, timeout=60, check=False)
