"""Events and event handlers: process start/exit/IO, completion, shutdown, targeting."""
from __future__ import annotations

import sys

from launch.actions import (
    EmitEvent,
    ExecuteProcess,
    LogInfo,
    OpaqueFunction,
    RegisterEventHandler,
    TimerAction,
    UnregisterEventHandler,
)
from launch.event_handlers import (
    OnExecutionComplete,
    OnProcessExit,
    OnProcessIO,
    OnProcessStart,
    OnShutdown,
)
from launch.events import Shutdown, matches_action
from launch.events.process import ShutdownProcess, SignalProcess
from launch.substitutions import LocalSubstitution

PY = sys.executable


def test_start_and_exit_handlers_target_one_action(run_launch):
    first = ExecuteProcess(cmd=[PY, '-c', 'import sys; sys.exit(3)'], name='first')
    second = ExecuteProcess(cmd=['true'], name='second')
    result = run_launch([
        RegisterEventHandler(OnProcessStart(target_action=first,
                                            on_start=[LogInfo(msg='first started')])),
        RegisterEventHandler(OnProcessExit(
            target_action=first,
            on_exit=[LogInfo(msg=['first exited with ', LocalSubstitution('event.returncode')]),
                     ExecuteProcess(cmd=['true'], name='after_first')])),
        first, second,
    ])
    assert result.user_lines() == ['first started', 'first exited with 3']
    assert result.names == ['first-1', 'second-2', 'after_first-3']
    assert '[ERROR] [first-1]: process has died [pid ' in result.output
    assert f", exit code 3, cmd '{PY} -c import sys; sys.exit(3)']." in result.output
    assert '[INFO] [second-2]: process has finished cleanly [pid ' in result.output


def test_callable_handlers_and_predicate_targets(run_launch):
    seen = []
    result = run_launch([
        RegisterEventHandler(OnProcessExit(
            target_action=lambda action: action.process_details['name'].startswith('b'),
            on_exit=lambda event, context: seen.append((event.process_name, event.returncode)))),
        ExecuteProcess(cmd=['true'], name='a'),
        ExecuteProcess(cmd=['false'], name='b'),
    ])
    assert result.returncode == 0
    assert seen == [('b-2', 1)]


def test_process_io_events_carry_bytes_per_stream(run_launch):
    out, err = [], []
    proc = ExecuteProcess(cmd=[PY, '-c', 'import sys; print("to out"); '
                                         'sys.stderr.write("to err\\n")'], name='talky')
    run_launch([RegisterEventHandler(OnProcessIO(target_action=proc,
                                                 on_stdout=lambda e: out.append(e.text),
                                                 on_stderr=lambda e: err.append(e.text))),
                proc])
    assert b''.join(out) == b'to out\n'
    assert b''.join(err) == b'to err\n'


def test_execution_complete_waits_for_processes_and_timers(run_launch):
    timer = TimerAction(period=0.05, actions=[LogInfo(msg='timer fired')])
    proc = ExecuteProcess(cmd=['true'], name='quick')
    result = run_launch([
        RegisterEventHandler(OnExecutionComplete(target_action=timer,
                                                 on_completion=[LogInfo(msg='timer done')])),
        RegisterEventHandler(OnExecutionComplete(target_action=proc,
                                                 on_completion=[LogInfo(msg='proc done')])),
        timer, proc,
    ])
    assert sorted(result.user_lines()) == ['proc done', 'timer done', 'timer fired']
    assert result.user_lines().index('timer fired') < result.user_lines().index('timer done')


def test_shutdown_handlers_run_when_idle_and_after_errors(run_launch):
    reasons = []

    def record(event, context):
        reasons.append(event.reason)

    assert run_launch([RegisterEventHandler(OnShutdown(on_shutdown=record))]).returncode == 0

    def fail(context):
        raise RuntimeError('broken on purpose')

    result = run_launch([RegisterEventHandler(OnShutdown(on_shutdown=record)),
                         OpaqueFunction(function=fail)])
    assert result.returncode == 1
    assert reasons[0] == 'idle'
    assert 'broken on purpose' in reasons[1]


def test_unregister_and_handle_once(run_launch):
    counted = []
    once = OnProcessStart(on_start=lambda e, c: counted.append('once'), handle_once=True)
    removed = OnProcessStart(on_start=lambda e, c: counted.append('removed'))
    run_launch([
        RegisterEventHandler(once), RegisterEventHandler(removed),
        UnregisterEventHandler(removed),
        ExecuteProcess(cmd=['true']), ExecuteProcess(cmd=['true']),
    ])
    assert counted == ['once']


def test_targeted_process_events(run_launch):
    # ProcessStdin is a ProcessIO event, not a targeted one: test_process_stdin.py
    stubborn = ExecuteProcess(cmd=['sleep', '20'], name='target')
    result = run_launch([
        stubborn,
        TimerAction(period=0.3, actions=[
            EmitEvent(event=SignalProcess(signal_number='SIGUSR1',
                                          process_matcher=matches_action(stubborn))),
        ]),
    ])
    assert "[INFO] [target-1]: sending signal 'SIGUSR1' to process[target-1]" in result.output
    assert 'exit code -10' in result.output


def test_shutdown_process_event_stops_only_its_target(run_launch):
    keep = ExecuteProcess(cmd=['sleep', '0.6'], name='keep')
    stop = ExecuteProcess(cmd=['sleep', '20'], name='stop')
    result = run_launch([keep, stop, TimerAction(period=0.1, actions=[
        EmitEvent(event=ShutdownProcess(process_matcher=matches_action(stop)))])])
    assert "sending signal 'SIGINT' to process[stop-2]" in result.output
    assert '[INFO] [keep-1]: process has finished cleanly' in result.output


def test_opaque_coroutine_is_awaited_and_cancelled_on_shutdown(run_launch):
    import asyncio

    from launch.actions import OpaqueCoroutine

    finished, cancelled = [], []

    async def quick(context, word):
        await asyncio.sleep(0.05)
        finished.append(word)

    async def forever():
        try:
            await asyncio.sleep(60)
        except asyncio.CancelledError:
            cancelled.append(True)
            raise

    run_launch([OpaqueCoroutine(coroutine=quick, args=['done'])])
    assert finished == ['done']
    result = run_launch([OpaqueCoroutine(coroutine=forever, ignore_context=True)],
                        shutdown_after=0.1)
    assert cancelled == [True]
    assert result.returncode == 0


def test_every_shutdown_event_reaches_on_shutdown_handlers(run_launch):
    """Observed on Jazzy: a second Shutdown event (a second critical process
    exiting) runs the OnShutdown handlers again, and a process that is already
    stopping is not signalled again."""
    first = ExecuteProcess(cmd=['true'], name='first')
    second = ExecuteProcess(cmd=['sleep', '30'], name='second')
    result = run_launch([
        first, second,
        RegisterEventHandler(OnShutdown(
            on_shutdown=lambda event, _context: [LogInfo(msg=f'on shutdown: {event.reason}')])),
        RegisterEventHandler(OnProcessExit(
            target_action=first, on_exit=[EmitEvent(event=Shutdown(reason='first'))])),
        RegisterEventHandler(OnProcessExit(
            target_action=second, on_exit=[EmitEvent(event=Shutdown(reason='second'))])),
    ])
    assert result.user_lines() == ['on shutdown: first', 'on shutdown: second']
    assert result.output.count("sending signal 'SIGINT' to process[second-2]") == 1
    assert result.returncode == 0
