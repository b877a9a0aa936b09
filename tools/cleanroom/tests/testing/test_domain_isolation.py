"""launch_testing's domain leases share domain_coordinator with every other holder."""
from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator

import pytest
from launch_testing.domain_isolation import lease_domain

# Another program holding an ID through the library itself, as ROS 2's isolated
# tests (ament_cmake_ros) and the book's tools do.
HOLDER = """
import itertools, sys
import domain_coordinator
ids = itertools.cycle(range(1, 90))
with domain_coordinator.domain_id(selector=lambda: next(ids)) as domain_id:
    print(domain_id, flush=True)
    sys.stdin.read()
"""


@pytest.fixture
def holder() -> Iterator[tuple[subprocess.Popen, int]]:
    proc = subprocess.Popen([sys.executable, '-c', HOLDER], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True)
    try:
        line = proc.stdout.readline()
        assert line.strip().isdigit(), f'the holder process leased nothing: {line!r}'
        yield proc, int(line)
    finally:
        proc.kill()
        proc.wait()


def test_an_id_held_elsewhere_is_skipped_and_comes_back_when_its_holder_dies(holder):
    proc, held = holder
    with lease_domain() as mine:
        assert mine.domain_id != held and 1 <= mine.domain_id <= 89
    with pytest.raises(RuntimeError) as error:
        lease_domain(timeout=0, ids=range(held, held + 1))
    assert str(error.value) == (
        f'no free ROS domain: IDs {held}-{held} are all held by other runs on this machine '
        f'(domain_coordinator binds TCP port 32768 + ID: ports {32768 + held}-'
        f'{32768 + held} are all in use; too many runs at once?)')
    proc.kill()
    proc.wait()
    with lease_domain(timeout=0, ids=range(held, held + 1)) as lease:
        assert lease.domain_id == held


def test_two_leases_of_one_process_differ_and_a_released_id_is_free_again():
    with lease_domain() as first, lease_domain() as second:
        assert first.domain_id != second.domain_id
    with lease_domain(timeout=0, ids=range(first.domain_id, first.domain_id + 1)) as again:
        assert again.domain_id == first.domain_id
