"""Domain leases (domain_coordinator, IDs 1-89) and the reaper."""
from __future__ import annotations

import os
import subprocess
import sys
import threading
import time
import types
from collections.abc import Iterator

import pytest
from domain_coordinator.impl import PORT_BASE
from rclhelpers import domains
from textbook import isolation, reaper

# Another process of this machine holding a lease, as a parallel test run or lesson would.
HOLDER = """
import sys
from textbook import isolation
lease = isolation.acquire_domain()
print(lease.domain_id, flush=True)
sys.stdin.read()  # held until the test closes stdin or kills this process
"""


def only(domain_id: int) -> range:
    return range(domain_id, domain_id + 1)


@pytest.fixture
def holder() -> Iterator[tuple[subprocess.Popen, int]]:
    """A separate process holding one lease; yields it and its domain ID."""
    proc = subprocess.Popen([sys.executable, '-c', HOLDER], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True)
    try:
        line = proc.stdout.readline()  # printed once the lease is held
        assert line.strip().isdigit(), f'the holder process leased nothing: {line!r}'
        yield proc, int(line)
    finally:
        proc.kill()
        proc.wait()


def test_leases_are_exclusive_in_range_and_released():
    with isolation.acquire_domain() as first, isolation.acquire_domain() as second:
        assert first.domain_id != second.domain_id
        assert {first.domain_id, second.domain_id} <= set(range(1, 90))
    with isolation.acquire_domain(timeout=0, ids=only(first.domain_id)) as again:
        assert again.domain_id == first.domain_id  # released ids are reused


def test_a_lease_held_by_another_process_is_never_handed_out(holder):
    proc, held = holder
    with isolation.acquire_domain() as mine:
        assert mine.domain_id != held
    with pytest.raises(RuntimeError) as error:
        isolation.acquire_domain(timeout=0, ids=only(held))
    assert str(error.value) == (
        f'no free ROS domain: IDs {held}-{held} are all held by other runs on this machine '
        f'(domain_coordinator binds TCP port {PORT_BASE} + ID: ports {PORT_BASE + held}-'
        f'{PORT_BASE + held} are all in use; too many runs at once?)')
    proc.kill()  # a holder that dies gives its ID back
    proc.wait()
    with isolation.acquire_domain(timeout=0, ids=only(held)) as lease:
        assert lease.domain_id == held


def test_a_full_range_waits_until_an_id_is_released(holder, monkeypatch):
    proc, held = holder
    waiting = threading.Event()

    def sleep(seconds: float) -> None:
        waiting.set()  # every ID of the range was taken: the allocator waits
        time.sleep(seconds)

    monkeypatch.setattr(domains, 'time', types.SimpleNamespace(monotonic=time.monotonic,
                                                                 sleep=sleep))
    leased: list[isolation.DomainLease] = []
    waiter = threading.Thread(target=lambda: leased.append(
        isolation.acquire_domain(timeout=60, ids=only(held))))
    waiter.start()
    try:
        assert waiting.wait(timeout=30), 'the allocator did not wait for a full range'
        assert not leased
        proc.stdin.close()  # the holder ends and releases its ID
        proc.wait()
    finally:
        waiter.join(timeout=90)
    assert [lease.domain_id for lease in leased] == [held]
    leased[0].release()


def test_the_session_lease_is_held_against_other_processes(session_lease):
    """Under -n 2 each worker runs this: its ID is refused to every other process."""
    assert os.environ['ROS_DOMAIN_ID'] == str(session_lease.domain_id)
    attempt = subprocess.run(
        [sys.executable, '-c', 'import sys; from textbook import isolation; '
         f'isolation.acquire_domain(timeout=0, ids=range({session_lease.domain_id}, '
         f'{session_lease.domain_id + 1}))'],
        capture_output=True, text=True, timeout=60)
    assert attempt.returncode != 0
    assert f'no free ROS domain: IDs {session_lease.domain_id}-{session_lease.domain_id}' \
        in attempt.stderr


def test_an_error_inside_a_lease_propagates_and_releases_it():
    with pytest.raises(FileNotFoundError), isolation.acquire_domain() as lease:
        raise FileNotFoundError('raised while the lease is held')
    with isolation.acquire_domain(timeout=0, ids=only(lease.domain_id)) as again:
        assert again.domain_id == lease.domain_id


def test_env_isolates_and_drops_wider_discovery_settings():
    with isolation.acquire_domain() as lease:
        env = lease.apply({'ROS_LOCALHOST_ONLY': '0', 'ROS_STATIC_PEERS': '10.0.0.2', 'A': 'b'})
    assert env['ROS_DOMAIN_ID'] == str(lease.domain_id)
    assert env['ROS_AUTOMATIC_DISCOVERY_RANGE'] == 'LOCALHOST'
    assert 'ROS_LOCALHOST_ONLY' not in env and 'ROS_STATIC_PEERS' not in env
    assert env['A'] == 'b' and env[isolation.LEASE_VAR] == lease.token


def test_reaper_stops_only_processes_of_its_lease():
    with isolation.acquire_domain() as mine, isolation.acquire_domain() as other:
        ours = subprocess.Popen(['sleep', '300'], env=mine.apply(dict(os.environ)))
        theirs = subprocess.Popen(['sleep', '300'], env=other.apply(dict(os.environ)))
        try:
            killed = reaper.reap([mine.token], grace=0.5)
            assert killed == [f'pid {ours.pid}: sleep 300']
            assert ours.wait(timeout=10) is not None
            assert theirs.poll() is None, 'the reaper killed a process of another lease'
            assert reaper.reap([mine.token], grace=0) == []
        finally:
            theirs.kill()
            theirs.wait()
            ours.kill()
            ours.wait()


def test_the_reaper_stops_a_ros2_daemon_without_calling_it_a_leftover(monkeypatch):
    """Jazzy's `ros2` leaves its daemon running on purpose (a command line as
    observed there: `... --name ros2-daemon --ros-domain-id N ...`); the build
    stops it after a lesson without failing the lesson, and waits for nothing."""
    daemon_like = [sys.executable, '-c', 'import time; time.sleep(300)', '--name', 'ros2-daemon',
                   '--ros-domain-id', '7']
    with isolation.acquire_domain() as mine:
        env = mine.apply(dict(os.environ))
        daemon = subprocess.Popen(daemon_like, env=env)
        other = subprocess.Popen(['sleep', '300'], env=env)
        try:
            assert reaper.reap([mine.token], grace=0.2) == [f'pid {other.pid}: sleep 300']
            assert daemon.wait(timeout=10) is not None
            daemon = subprocess.Popen(daemon_like, env=env)

            def no_waiting(_seconds: float) -> None:
                raise AssertionError('the reaper waited for the daemon to end by itself')

            with monkeypatch.context() as patch:
                patch.setattr(reaper.time, 'sleep', no_waiting)
                assert reaper.reap([mine.token], grace=30) == []
            assert daemon.wait(timeout=10) is not None
        finally:
            for proc in (daemon, other):
                proc.kill()
                proc.wait()


def test_an_id_just_given_back_is_not_the_next_one_handed_out():
    """A released ID may still carry the last run's lingering nodes: leases start at a
    random place in the range, so ten lease-release rounds do not keep getting one ID
    (all ten alike has a chance of about 89**-9 when the choice is random)."""
    seen = set()
    for _ in range(10):
        with isolation.acquire_domain() as lease:
            seen.add(lease.domain_id)
    assert len(seen) > 1, seen


def test_a_fixed_domain_is_held_by_one_run_at_a_time():
    """6.7's sensor in domain 101: while one run holds it, another waits for it."""
    with isolation.holding_fixed_domains([101]):
        with pytest.raises(RuntimeError, match='IDs 101-101 are all held'):
            with isolation.holding_fixed_domains([101], timeout=0):
                pass
    with isolation.holding_fixed_domains([101], timeout=0):
        pass  # given back when the first run ends


@pytest.mark.ros  # it starts a ROS 2 daemon
def test_a_fixed_domain_given_back_has_no_daemon_left(tmp_path):
    """The other stack may hold the domain next: a daemon of this one would answer its
    `ros2` on the same port (Jazzy's client got ConnectionResetError from ours)."""
    domain = '211'  # a fixed domain no lesson uses
    env = {**os.environ, 'ROS_DOMAIN_ID': domain, 'ROS_LOG_DIR': str(tmp_path)}
    ros2 = isolation.paths.executable('ros2')

    def status() -> str:
        return subprocess.run([ros2, 'daemon', 'status'], env=env, capture_output=True,
                              text=True, check=False).stdout.strip()
    with isolation.holding_fixed_domains([int(domain)]):
        subprocess.run([ros2, 'daemon', 'start'], env=env, capture_output=True, check=True)
        assert status() == 'The daemon is running'
    assert status() == 'The daemon is not running'
