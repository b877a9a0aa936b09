"""ProcessStdin: Jazzy's event for a process's standard input (recorded from launch 3.4.3).

It is a ProcessIO event (fields action, name, cmd, cwd, env, pid; from_stdin
true) and the process's own OnProcessIO handler takes it, but writes
nothing: it logs "in ExecuteProcess('<id of the action>').__on_process_stdin_event()"
as a warning of that process.  Other handlers (a user's OnProcessIO with
on_stdin) still see the event.
"""
from __future__ import annotations

import inspect
import sys

import pytest
from launch.actions import EmitEvent, ExecuteProcess, RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessIO, OnProcessStart
from launch.events.process import ProcessIO, ProcessStdin

PY = sys.executable
FIELDS = {'name': 'cat-1', 'cmd': ['cat'], 'cwd': None, 'env': None, 'pid': 1}


def test_is_a_process_io_event():
    assert ProcessStdin.__mro__[1] is ProcessIO
    assert [(p.name, p.kind.name) for p in inspect.signature(ProcessStdin).parameters.values()
            ] == [('text', 'KEYWORD_ONLY'), ('kwargs', 'VAR_KEYWORD')]
    action = ExecuteProcess(cmd=['cat'])
    event = ProcessStdin(text=b'x\n', action=action, **FIELDS)
    assert (event.text, event.from_stdin, event.from_stdout, event.from_stderr) == (
        b'x\n', True, False, False)
    assert event.action is action and event.execute_process_action is action
    assert (event.name, event.process_name, event.cmd, event.pid) == (
        'launch.events.process.ProcessStdin', 'cat-1', ['cat'], 1)
    assert ProcessStdin(text='not bytes', action=action, **FIELDS).text == 'not bytes'
    assert not hasattr(event, 'process_matcher')


def test_needs_the_running_process_fields():
    with pytest.raises(TypeError) as error:
        ProcessStdin(text=b'x')
    assert str(error.value) == (
        "RunningProcessEvent.__init__() missing 6 required keyword-only arguments: "
        "'action', 'name', 'cmd', 'cwd', 'env', and 'pid'")


def test_the_process_warns_and_reads_nothing(run_launch):
    # cat echoes whatever reaches its stdin: nothing may come out
    target = ExecuteProcess(cmd=['cat'], name='cat', output='screen')
    other = ExecuteProcess(cmd=['cat'], name='other', output='screen')
    seen = []

    def on_start(event, context):
        return EmitEvent(event=ProcessStdin(
            text=b'hello stdin\n', action=event.action, name=event.name, cmd=event.cmd,
            cwd=event.cwd, env=event.env, pid=event.pid))

    result = run_launch([
        RegisterEventHandler(OnProcessStart(target_action=target, on_start=on_start)),
        RegisterEventHandler(OnProcessIO(target_action=target,
                                         on_stdin=lambda event: seen.append(event.text),
                                         on_stdout=lambda event: seen.append(event.text))),
        target, other,
    ], shutdown_after=1.0)
    assert seen == [b'hello stdin\n']
    warnings = [line for line in result.output.splitlines() if '[WARNING]' in line]
    assert warnings == [
        f"[WARNING] [cat-1]: in ExecuteProcess('{id(target)}').__on_process_stdin_event()"]
    assert 'hello stdin' not in result.output


def test_timer_emitted_stdin_reaches_only_its_process(run_launch):
    target = ExecuteProcess(cmd=['cat'], name='target')
    result = run_launch([
        ExecuteProcess(cmd=['cat'], name='bystander'), target,
        TimerAction(period=0.5, actions=[EmitEvent(event=ProcessStdin(
            text=b'x\n', action=target, **FIELDS))]),
    ], shutdown_after=1.5)
    assert [line for line in result.output.splitlines() if 'stdin' in line] == [
        f"[WARNING] [target-2]: in ExecuteProcess('{id(target)}').__on_process_stdin_event()"]
