"""Nothing labkit starts survives its owner: killed kernel or normal exit.

The owner is a separate Python process standing in for a notebook kernel;
it starts a launch with labkit and prints the process group to watch.
"""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap

import pytest
from labkit import watchdog
from labkit.background import WATCHDOG
from labkit.watchdog import stop_group
from rclhelpers.processes import group_members

from .._polling import poll, still_running

OWNER = textwrap.dedent("""
    import sys, time
    import labkit
    run = labkit.launch('my_robot_pkg', 'robot_system.launch.py')
    run.wait_for_nodes(['/sensor_publisher', '/data_processor'])
    print(run.pid, run._watchdog.pid, flush=True)
    if sys.argv[1] == 'exit':
        sys.exit(0)  # leave without stop(): atexit must stop the launch
    time.sleep(600)
""")


def _wait_until_gone(pids: list[int], timeout: float) -> list[int]:
    """Poll until none of `pids` runs (zombies count as gone); return the survivors."""
    poll(lambda: not still_running(pids), timeout)
    return still_running(pids)


@pytest.fixture
def owner(ros_env):
    started = []

    def start(mode: str) -> tuple[subprocess.Popen, int, int]:
        proc = subprocess.Popen([sys.executable, '-c', OWNER, mode], env=ros_env,
                                stdout=subprocess.PIPE, text=True, start_new_session=True)
        started.append(proc)
        launch_pid, watchdog_pid = map(int, proc.stdout.readline().split())
        return proc, launch_pid, watchdog_pid

    yield start
    for proc in started:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


def test_watchdog_stops_the_launch_when_the_owner_is_killed(owner):
    proc, launch_pid, watchdog_pid = owner('sleep')
    launched = [p.pid for p in group_members(launch_pid)]
    assert len(launched) >= 3  # ros2 launch and its two nodes
    proc.kill()  # SIGKILL: no atexit, no cleanup in the owner
    proc.wait()
    survivors = _wait_until_gone(launched + [watchdog_pid], timeout=30)
    if survivors:  # leave nothing behind even when the assertion fails
        stop_group(launch_pid)
    assert survivors == []


def test_interpreter_exit_stops_what_is_still_running(owner):
    proc, launch_pid, watchdog_pid = owner('exit')
    assert proc.wait(timeout=60) == 0
    assert group_members(launch_pid) == []
    assert _wait_until_gone([watchdog_pid], timeout=10) == []


def test_watchdog_keeps_watching_a_live_group_and_exits_once_it_is_gone(monkeypatch):
    """In-process, with the poll counted instead of timed: while the owner and the
    group live, watch() keeps polling; the group's end makes it return 0."""
    sleeper = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(600)'],
                               start_new_session=True)
    polls = []

    def poll(_seconds: float) -> None:
        polls.append(sleeper.poll())  # None: the group was alive at this poll
        if len(polls) == 3:
            sleeper.kill()
            sleeper.wait()

    monkeypatch.setattr(watchdog.time, 'sleep', poll)
    try:
        assert watchdog.watch(os.getppid(), sleeper.pid) == 0
    finally:
        if sleeper.poll() is None:
            sleeper.kill()
            sleeper.wait()
    assert polls == [None, None, None]  # three polls with the group alive, then it ended


def test_watchdog_usage_error():
    result = subprocess.run([sys.executable, WATCHDOG, 'x'], capture_output=True, text=True)
    assert (result.returncode, result.stderr) == (
        2, 'usage: watchdog.py OWNER_PID PGID\n')


def test_sigterm_ends_the_watchdog_at_once_without_the_interpreters_shutdown():
    # Its SIGTERM can arrive while it is exiting by itself; a SystemExit raised then
    # would print `Exception ignored in: <module 'threading'...` into the lesson.
    code = ('import atexit, os, signal, sys\n'
            f'sys.path.insert(0, {os.path.dirname(WATCHDOG)!r})\n'
            'import watchdog\n'
            "atexit.register(print, 'interpreter shutdown ran')\n"
            'watchdog.handle_signals()\n'
            'os.kill(os.getpid(), signal.SIGTERM)\n'
            'signal.pause()\n')
    result = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True,
                            timeout=30)
    assert (result.returncode, result.stdout, result.stderr) == (0, '', '')


def _execute(client, code: str, timeout: float = 120) -> list[dict]:
    """Run a cell; return its output messages (stream, display, result, error)."""
    msg_id = client.execute(code)
    outputs = []
    while True:
        msg = client.get_iopub_msg(timeout=timeout)
        if msg['parent_header'].get('msg_id') != msg_id:
            continue
        if msg['msg_type'] == 'status' and msg['content']['execution_state'] == 'idle':
            return outputs
        if msg['msg_type'] in ('stream', 'display_data', 'execute_result', 'error'):
            outputs.append(msg)


def test_in_a_notebook_kernel_the_graph_displays_once_and_a_dead_kernel_leaves_nothing(
        ros_env, tmp_path):
    from jupyter_client.manager import start_new_kernel

    manager, client = start_new_kernel(kernel_name='python3', env=ros_env, cwd=str(tmp_path))
    try:
        outputs = _execute(client, textwrap.dedent("""
            import os, labkit
            run = labkit.launch('my_robot_pkg', 'robot_system.launch.py')
            run.wait_for_nodes(['/sensor_publisher', '/data_processor'])
            print(run.pid, os.getpid())
            labkit.draw_graph()
        """))
        assert not [o for o in outputs if o['msg_type'] == 'error'], outputs
        launch_pid, kernel_pid = map(int, next(
            o for o in outputs if o['msg_type'] == 'stream')['content']['text'].split())
        images = [o for o in outputs if 'image/png' in o['content'].get('data', {})]
        assert len(images) == 1  # the returned Figure, shown once
        launched = [p.pid for p in group_members(launch_pid)]
        assert len(launched) >= 3
        os.kill(kernel_pid, signal.SIGKILL)  # the kernel dies without cleanup
        survivors = _wait_until_gone(launched, timeout=30)
        if survivors:
            stop_group(launch_pid)
        assert survivors == []
    finally:
        client.stop_channels()
        manager.shutdown_kernel(now=True)
