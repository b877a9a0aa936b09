"""Domain leases and the reaper."""
from __future__ import annotations

import os
import signal
import subprocess
import time

from textbook import isolation, reaper


def test_leases_are_exclusive_and_in_range(tmp_path, monkeypatch):
    monkeypatch.setenv('TMPDIR', str(tmp_path))
    with isolation.acquire_domain() as first, isolation.acquire_domain() as second:
        assert first.domain_id != second.domain_id
        assert {first.domain_id, second.domain_id} <= set(range(1, 90))
        assert (tmp_path / 'ros2-textbook-domains' / f'{first.domain_id}.lock').exists()
    with isolation.acquire_domain() as again:
        assert again.domain_id == first.domain_id  # released ids are reused


def test_a_lease_held_by_another_process_is_skipped(tmp_path, monkeypatch):
    monkeypatch.setenv('TMPDIR', str(tmp_path))
    lock = tmp_path / 'ros2-textbook-domains' / '1.lock'
    lock.parent.mkdir()
    holder = subprocess.Popen(['flock', '--exclusive', str(lock), 'sleep', '30'],
                              start_new_session=True)
    try:
        for _ in range(50):
            if subprocess.run(['flock', '-n', str(lock), 'true']).returncode != 0:
                break
            time.sleep(0.1)
        with isolation.acquire_domain() as lease:
            assert lease.domain_id == 2
    finally:
        os.killpg(holder.pid, signal.SIGKILL)  # flock and its sleep
        holder.wait()


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
