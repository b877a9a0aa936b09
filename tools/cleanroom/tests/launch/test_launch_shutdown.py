"""Shutdown: SIGINT, then SIGTERM, then SIGKILL; signals to `ros2 launch` reap children."""
from __future__ import annotations

import os
import pty
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import psutil
import pytest
from launch.actions import EmitEvent, ExecuteProcess, LogInfo, RegisterEventHandler, Shutdown
from launch.event_handlers import OnProcessExit, OnProcessIO, OnProcessStart
from launch.events import Shutdown as ShutdownEvent

ROS2 = str(Path(sys.executable).parent / 'ros2')  # the ros2 of this environment

IGNORE_INT_AND_TERM = ('import signal, time; signal.signal(signal.SIGINT, signal.SIG_IGN); '
                       'signal.signal(signal.SIGTERM, signal.SIG_IGN); '
                       'print("ready", flush=True); time.sleep(30)')
IGNORE_INT_ONLY = ('import signal, sys, time; signal.signal(signal.SIGINT, signal.SIG_IGN); '
                   'signal.signal(signal.SIGTERM, lambda *a: sys.exit(0)); '
                   'print("ready", flush=True); time.sleep(30)')


def _shutdown_when_ready(action: ExecuteProcess) -> RegisterEventHandler:
    """Shut down once the child printed 'ready' (its signal handlers are in place)."""
    return RegisterEventHandler(OnProcessIO(
        target_action=action,
        on_stdout=lambda event: [Shutdown(reason='test')] if b'ready' in event.text else None))


def test_child_ignoring_sigint_and_sigterm_gets_sigkill(run_launch):
    stubborn = ExecuteProcess(cmd=[sys.executable, '-c', IGNORE_INT_AND_TERM], name='stubborn',
                              sigterm_timeout='0.2', sigkill_timeout='0.3')
    result = run_launch([_shutdown_when_ready(stubborn), stubborn])
    lines = [line for line in result.output.splitlines() if '[stubborn-1]' in line]
    assert lines[1:5] == [
        "[INFO] [stubborn-1]: sending signal 'SIGINT' to process[stubborn-1]",
        "[ERROR] [stubborn-1]: process[stubborn-1] failed to terminate '0.2' seconds after "
        "receiving 'SIGINT', escalating to 'SIGTERM'",
        "[INFO] [stubborn-1]: sending signal 'SIGTERM' to process[stubborn-1]",
        "[ERROR] [stubborn-1]: process[stubborn-1] failed to terminate '0.5' seconds after "
        "receiving 'SIGTERM', escalating to 'SIGKILL'",
    ]
    assert lines[5] == "[INFO] [stubborn-1]: sending signal 'SIGKILL' to process[stubborn-1]"
    assert 'exit code -9' in lines[6]
    assert result.returncode == 0


def test_child_ignoring_sigint_stops_at_sigterm(run_launch):
    polite = ExecuteProcess(cmd=[sys.executable, '-c', IGNORE_INT_ONLY], name='polite')
    result = run_launch([_shutdown_when_ready(polite), polite],
                        argv=('sigterm_timeout:=0.2',))
    assert "sending signal 'SIGTERM' to process[polite-1]" in result.output
    assert 'SIGKILL' not in result.output
    assert '[INFO] [polite-1]: process has finished cleanly' in result.output


@pytest.fixture
def start_launch(cli_env: dict) -> Iterator[Callable[..., subprocess.Popen]]:
    """Start `ros2 launch ARGS` and return it once its 4 processes have started.

    `terminal=True` gives it a pseudo-terminal as standard input, as a shell
    in a terminal does; otherwise its stdin is /dev/null, as in a script, CI
    or a notebook.  Whatever the test does, the launch is killed and reaped
    afterwards.
    """
    started: list[subprocess.Popen] = []
    terminals: list[int] = []

    def start(*args: str, terminal: bool = False) -> subprocess.Popen:
        stdin: int = subprocess.DEVNULL
        if terminal:
            main_side, stdin = pty.openpty()
            terminals.append(main_side)
        proc = subprocess.Popen([ROS2, 'launch', *args], env=cli_env, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, stdin=stdin,
                                start_new_session=True)  # its own group, as in a terminal
        if terminal:
            os.close(stdin)
        started.append(proc)
        _wait_for_starts(proc, 4)
        return proc

    yield start
    for proc in started:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
    for main_side in terminals:
        os.close(main_side)


def _wait_for_starts(proc: subprocess.Popen, count: int) -> list[str]:
    lines: list[str] = []
    deadline = time.monotonic() + 20
    while sum('process started' in line for line in lines) < count:
        line = proc.stdout.readline()
        assert line and time.monotonic() < deadline, lines
        lines.append(line.rstrip('\n'))
    return lines


def _children(proc: subprocess.Popen) -> list[psutil.Process]:
    return psutil.Process(proc.pid).children(recursive=True)


def test_ctrl_c_stops_all_children(start_launch):
    """Ctrl-C in a terminal: SIGINT to the whole group; the launch does not send it again."""
    proc = start_launch('cr_pkg', 'procs.launch.py', terminal=True)
    children = _children(proc)
    assert len(children) >= 3  # the sleepers; 'hello' may already have exited
    os.killpg(proc.pid, signal.SIGINT)
    out, _ = proc.communicate(timeout=20)
    assert proc.returncode == 0
    assert '[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)' in out
    assert "sending signal 'SIGINT'" not in out
    assert '[ERROR] [sleeper-1]: process has died [pid' in out and 'exit code -2' in out
    _gone, alive = psutil.wait_procs(children, timeout=5)
    assert not alive


def test_sigint_to_the_launch_only_escalates_to_sigterm(start_launch):
    """Interactive launch, SIGINT to it alone: children get SIGTERM after sigterm_timeout."""
    proc = start_launch('cr_pkg', 'procs.launch.py', 'sigterm_timeout:=0.3', terminal=True)
    children = _children(proc)
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=20)
    assert proc.returncode == 0
    assert ("[ERROR] [sleeper-1]: process[sleeper-1] failed to terminate '0.3' seconds after "
            "receiving 'SIGINT', escalating to 'SIGTERM'") in out
    _gone, alive = psutil.wait_procs(children, timeout=5)
    assert not alive


def _signal_launch(proc: subprocess.Popen, signum: int) -> str:
    """Send `signum` to `ros2 launch` alone; it must exit 0 and take every child along.
    Returns its output."""
    children = _children(proc)
    proc.send_signal(signum)
    out, _ = proc.communicate(timeout=20)
    assert proc.returncode == 0
    _gone, alive = psutil.wait_procs(children, timeout=5)
    assert not alive
    return out


def test_sigint_to_a_noninteractive_launch_is_sent_on(start_launch):
    out = _signal_launch(start_launch('--noninteractive', 'cr_pkg', 'procs.launch.py'),
                         signal.SIGINT)
    assert "sending signal 'SIGINT' to process[sleeper-2]" in out
    assert 'escalating' not in out


def test_a_launch_without_a_terminal_is_noninteractive(start_launch):
    """As Jazzy's: stdin not a terminal turns --noninteractive on; SIGINT is sent on at once."""
    out = _signal_launch(start_launch('cr_pkg', 'procs.launch.py'), signal.SIGINT)
    assert "[INFO] [sleeper-1]: sending signal 'SIGINT' to process[sleeper-1]" in out
    assert 'escalating' not in out


def test_sigterm_to_ros2_launch_stops_all_children(start_launch):
    out = _signal_launch(start_launch('cr_pkg', 'procs.launch.py'), signal.SIGTERM)
    assert "sending signal 'SIGINT' to process[sleeper-3]" in out


def test_killed_launch_takes_its_children_along(start_launch):
    proc = start_launch('cr_pkg', 'procs.launch.py')
    children = _children(proc)
    os.kill(proc.pid, signal.SIGKILL)
    proc.communicate(timeout=20)
    _gone, alive = psutil.wait_procs(children, timeout=5)
    assert not alive


def test_shutdown_while_processes_are_still_starting(run_launch):
    """A Shutdown queued with the processes reaches them once they have started."""
    result = run_launch([ExecuteProcess(cmd=['sleep', '20'], name=f's{i}') for i in range(5)]
                        + [Shutdown(reason='at once')])
    assert sorted(result.names) == [f's{i}-{i + 1}' for i in range(5)]
    assert result.output.count("sending signal 'SIGINT'") == 5
    assert 'escalating' not in result.output


REQUIRED = '[INFO] [launch]: process[{}] was required: shutting down launched system'


@pytest.mark.parametrize('code, ended', [
    (0, '[INFO] [critical-2]: process has finished cleanly'),
    (3, '[ERROR] [critical-2]: process has died'),
])
def test_a_required_process_exit_is_logged_before_the_shutdown(run_launch, code, ended):
    """Observed on Jazzy with `ExecuteProcess(..., on_exit=Shutdown())`, whatever the exit code.

    The launch logger says which process was required, right after that
    process's exit line and before the others are signalled.
    """
    result = run_launch([
        ExecuteProcess(cmd=['sleep', '20'], name='bystander'),
        ExecuteProcess(cmd=['sh', '-c', f'sleep 0.3; exit {code}'], name='critical',
                       on_exit=Shutdown())])
    lines = result.output.splitlines()
    required = lines.index(REQUIRED.format('critical-2'))
    assert lines[required - 1].startswith(ended)
    assert lines[required + 1] == "[INFO] [bystander-1]: sending signal 'SIGINT' to " \
        'process[bystander-1]'
    assert result.returncode == 0


def test_only_a_shutdown_run_by_a_process_exit_names_the_process(run_launch):
    """Observed on Jazzy: an OnProcessExit handler's Shutdown logs it too; a Shutdown
    started by a process start, or an EmitEvent of the Shutdown event, does not.
    """
    exits = ExecuteProcess(cmd=['true'], name='exits')
    starts = ExecuteProcess(cmd=['sleep', '20'], name='starts')
    handled = run_launch([exits, RegisterEventHandler(OnProcessExit(
        target_action=exits, on_exit=[LogInfo(msg='exited'), Shutdown()]))])
    assert REQUIRED.format('exits-1') in handled.output.splitlines()
    started = run_launch([starts, RegisterEventHandler(OnProcessStart(
        target_action=starts, on_start=[Shutdown()]))])
    emitted = run_launch([ExecuteProcess(cmd=['true'], name='emits',
                                         on_exit=EmitEvent(event=ShutdownEvent()))])
    assert 'was required' not in started.output + emitted.output
