"""labkit.processes: CPU and memory of a launch's processes over a window,
each named by its node (or program), busiest first."""
from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Iterator

import labkit
import psutil
import pytest
from labkit.processes import launch_processes, process_name, process_usage

from tests._polling import wait_for

WINDOW = 2.0  # seconds of measurement
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging
BUSY = 'while True: pass'
IDLE = 'import sys; sys.stdin.read()'  # blocks until its stdin closes


@pytest.fixture
def busy_and_idle() -> Iterator[tuple[subprocess.Popen, subprocess.Popen]]:
    busy = subprocess.Popen([sys.executable, '-c', BUSY])
    idle = subprocess.Popen([sys.executable, '-c', IDLE], stdin=subprocess.PIPE)
    try:
        yield busy, idle
    finally:
        busy.kill()
        idle.kill()
        busy.wait()
        idle.wait()


def test_names_come_from_the_node_name_or_the_program():
    assert process_name(['/usr/bin/python3', '/ws/lib/pkg/camera', '--ros-args', '-r',
                         '__node:=front_camera', '--params-file', '/tmp/p']) == 'front_camera'
    assert process_name(['/usr/bin/python3', '/ws/lib/pkg/camera']) == 'camera'
    assert process_name(['/opt/ros/jazzy/lib/pkg/talker_cpp']) == 'talker_cpp'
    assert process_name(['/venv/bin/python', '/venv/bin/ros2', 'launch', 'pkg', 'x.py']) \
        == 'ros2'
    assert process_name(['python3', '-m', 'labkit.watchdog', '1', '2']) == 'labkit.watchdog'
    assert process_name(['python3', '-c', 'pass']) == 'python3'
    assert process_name([]) == '?'


def test_a_busy_process_uses_more_cpu_than_an_idle_one(busy_and_idle):
    busy, idle = busy_and_idle
    usage = process_usage([idle.pid, busy.pid], window=WINDOW)
    assert [item.pid for item in usage] == [busy.pid, idle.pid], usage
    assert usage[0].cpu_percent > 10 * usage[1].cpu_percent, usage
    assert usage[1].rss == pytest.approx(psutil.Process(idle.pid).memory_info().rss, rel=0.5)
    assert usage[0].name == os.path.basename(sys.executable) and BUSY in usage[0].command


def test_a_background_command_is_measured_with_everything_it_started():
    python = os.path.basename(sys.executable)
    script = f'{sys.executable} -c "{BUSY}" & {sys.executable} -c "{BUSY}" & wait'
    with labkit.start(['bash', '-c', script]) as run:
        wait_for(lambda: _names(launch_processes(run)) == ['bash', python, python],
                 HANG_GUARD, 'bash running its two busy children')
        started = {process.pid for process in launch_processes(run)}
        usage = process_usage(run, window=WINDOW)
    assert {item.pid for item in usage} == started and run.pid in started
    assert sorted(item.name for item in usage) == ['bash', python, python]
    assert [item.name for item in usage][:2] == [python, python], usage


def _names(processes: list[psutil.Process]) -> list[str]:
    try:
        return sorted(process_name(process.cmdline()) for process in processes)
    except psutil.Error:  # a child between fork and exec, or gone
        return []


def test_a_process_that_is_gone_is_an_error():
    process = subprocess.Popen([sys.executable, '-c', 'pass'])
    process.wait()
    with pytest.raises(labkit.LabkitError, match=f'process {process.pid} is not running'):
        launch_processes(process.pid)
