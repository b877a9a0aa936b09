"""`ros2 launch -d`: the DEBUG lines Jazzy prints, for the same launch files.

Observed on Jazzy (ros2 launch -d FILE): the context logs each event it
queues ('emitting event' from its coroutine, 'emitting event synchronously'
otherwise), the service logs each event it takes from the queue and then,
with a check mark, each handler that takes it, before running that handler;
an exception that ends the launch is logged with its traceback.  Object
reprs are Python's defaults (`<module.Class object at 0x...>`).
"""
from __future__ import annotations

import re
from pathlib import Path

from launch.actions import LogInfo

ADDR = '0x[0-9a-f]+'
EMIT = "[DEBUG] [launch.launch_context]: emitting event: '{}'"
EMIT_SYNC = "[DEBUG] [launch.launch_context]: emitting event synchronously: '{}'"
INCLUDE_EVENT = 'launch.events.include_launch_description.IncludeLaunchDescription'
SHUTDOWN_EVENT = 'launch.events.shutdown.Shutdown'
ON_SHUTDOWN = 'launch.event_handlers.on_shutdown.OnShutdown'
ON_EXIT = 'launch.event_handlers.on_process_exit.OnProcessExit'


def processing(event_cls: str, handler_cls: str | None = None) -> str:
    """The regex of a 'processing event' line, with a handler after the check mark if given."""
    line = re.escape(f"[DEBUG] [launch]: processing event: '<{event_cls} object at ") + \
        ADDR + ">'"
    if handler_cls is not None:
        line += re.escape(f" ✓ '<{handler_cls} object at ") + ADDR + ">'"
    return line


def _launch_d(ros2, tmp_path: Path, body: str) -> list[str]:
    path = tmp_path / 'debug.launch.py'
    path.write_text('from launch import LaunchDescription\n' + body)
    result = ros2('launch', '-d', str(path))
    assert result.stderr == '' or 'Executing <' in result.stderr, result.stderr  # asyncio debug
    return result.stdout.splitlines()


def _index(lines: list[str], pattern: str, start: int = 0) -> int:
    """Index of the first line from `start` matching the regex `pattern` entirely."""
    for i in range(start, len(lines)):
        if re.fullmatch(pattern, lines[i]):
            return i
    raise AssertionError(f'no line matches {pattern!r} after line {start}:\n' + '\n'.join(lines))


def test_events_and_the_handlers_taking_them(ros2, tmp_path):
    lines = _launch_d(ros2, tmp_path, """
from launch.actions import ExecuteProcess
def generate_launch_description():
    return LaunchDescription([ExecuteProcess(cmd=['echo', 'hi'], output='screen')])
""")
    # Queued by `ros2 launch` before the service runs and says where the logs are.
    assert lines[0] == EMIT_SYNC.format('launch.events.IncludeLaunchDescription')
    assert lines[1].startswith('[INFO] [launch]: All log files can be found below ')
    assert lines[2] == '[INFO] [launch]: Default logging verbosity is set to DEBUG'
    assert re.fullmatch(processing(INCLUDE_EVENT), lines[3])
    assert re.fullmatch(processing(
        INCLUDE_EVENT,
        'launch.event_handlers.on_include_launch_description.OnIncludeLaunchDescription'),
        lines[4])
    # Output is printed by the process's OnProcessIO handler when its event is handled.
    assert EMIT_SYNC.format('launch.events.process.ProcessStdout') in lines
    stdout = _index(lines, processing('launch.events.process.process_stdout.ProcessStdout',
                                      'launch.event_handlers.on_process_io.OnProcessIO'))
    assert lines[stdout + 1] == '[echo-1] hi'
    assert lines.index(EMIT.format('launch.events.process.ProcessStarted')) \
        == _index(lines, r'\[INFO\] \[echo-1\]: process started with pid \[\d+\]') + 1
    _index(lines, processing('launch.events.process.process_started.ProcessStarted'))
    exited = lines.index(EMIT.format('launch.events.process.ProcessExited'))
    assert re.fullmatch(r'\[INFO\] \[echo-1\]: process has finished cleanly \[pid \d+\]',
                        lines[exited - 1])
    event = _index(lines, processing('launch.events.process.process_exited.ProcessExited'),
                   exited)
    exit_handler = processing('launch.events.process.process_exited.ProcessExited', ON_EXIT)
    assert all(re.fullmatch(exit_handler, line) for line in lines[event + 1:event + 3])
    # Idle: the service emits Shutdown; the process's and the service's own handlers take it.
    assert lines[-4] == EMIT.format('launch.events.Shutdown')
    assert re.fullmatch(processing(SHUTDOWN_EVENT), lines[-3])
    assert all(re.fullmatch(processing(SHUTDOWN_EVENT, ON_SHUTDOWN), line)
               for line in lines[-2:])


def test_shutdown_signals_a_running_process_through_an_event(ros2, tmp_path):
    lines = _launch_d(ros2, tmp_path, """
from launch.actions import ExecuteProcess, Shutdown, TimerAction
def generate_launch_description():
    return LaunchDescription([ExecuteProcess(cmd=['sleep', '30']),
                              TimerAction(period=0.5, actions=[Shutdown()])])
""")
    timer = _index(lines, processing('launch.events.timer_event.TimerEvent',
                                     'launch.event_handler.EventHandler'))
    assert lines[timer - 2] == EMIT.format('launch.events.TimerEvent')
    signal_event = 'launch.events.process.signal_process.SignalProcess'
    assert lines[timer + 1] == EMIT_SYNC.format('launch.events.Shutdown')
    expected = [
        processing(SHUTDOWN_EVENT),
        processing(SHUTDOWN_EVENT, 'launch.event_handler.EventHandler'),  # the timer's
        processing(SHUTDOWN_EVENT, ON_SHUTDOWN),  # the process's: it emits the SIGINT event
        re.escape(EMIT_SYNC.format('launch.events.process.SignalProcess')),
        processing(SHUTDOWN_EVENT, ON_SHUTDOWN),  # the service's own
        processing(signal_event),
        processing(signal_event, 'launch.event_handler.EventHandler'),
        re.escape("[INFO] [sleep-1]: sending signal 'SIGINT' to process[sleep-1]"),
        re.escape('[ERROR] [sleep-1]: process has died [pid ') + r'\d+' +
        re.escape(", exit code -2, cmd 'sleep 30']."),
        re.escape(EMIT.format('launch.events.process.ProcessExited')),
    ]
    for offset, pattern in enumerate(expected):
        assert re.fullmatch(pattern, lines[timer + 2 + offset]), (pattern, lines)


def test_a_user_handler_runs_before_the_process_own_exit_handlers(ros2, tmp_path):
    """Handlers are taken newest first; each one's actions run before the next is listed."""
    lines = _launch_d(ros2, tmp_path, """
from launch.actions import ExecuteProcess, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit
def generate_launch_description():
    p = ExecuteProcess(cmd=['true'])
    return LaunchDescription([p, RegisterEventHandler(OnProcessExit(
        target_action=p, on_exit=[LogInfo(msg='done')]))])
""")
    event = 'launch.events.process.process_exited.ProcessExited'
    first = _index(lines, processing(event, ON_EXIT))
    assert lines[first + 1] == '[INFO] [launch.user]: done'
    assert all(re.fullmatch(processing(event, ON_EXIT), line)
               for line in lines[first + 2:first + 4])


def test_an_exception_is_logged_with_its_traceback(ros2, tmp_path):
    lines = _launch_d(ros2, tmp_path, """
def generate_launch_description():
    raise RuntimeError('boom')
""")
    caught = lines.index('[DEBUG] [launch]: An exception was raised in an async action/event')
    assert lines[caught + 1] == '[DEBUG] [launch]: Traceback (most recent call last):'
    error = _index(lines, re.escape('[ERROR] [launch]: Caught exception in launch '
                                    '(see debug for traceback): ') + '.*', caught)
    assert 'RuntimeError: boom' in lines[caught:error]
    assert lines[error - 1] == ''  # the traceback's own last newline
    assert lines[-3] == EMIT.format('launch.events.Shutdown')
    assert re.fullmatch(processing(SHUTDOWN_EVENT, ON_SHUTDOWN), lines[-1])  # the service's


def test_a_missing_executable_is_logged_with_its_traceback(ros2, tmp_path):
    """Jazzy prints this traceback with and without -d."""
    lines = _launch_d(ros2, tmp_path, """
from launch.actions import ExecuteProcess
def generate_launch_description():
    return LaunchDescription([ExecuteProcess(cmd=['no_such_exe_xyz'])])
""")
    error = lines.index('[ERROR] [no_such_exe_xyz-1]: exception occurred while executing process:')
    assert lines[error + 1] == 'Traceback (most recent call last):'
    end = lines.index("FileNotFoundError: [Errno 2] No such file or directory: 'no_such_exe_xyz'")
    assert lines[end + 1:end + 3] == ['', EMIT.format('launch.events.Shutdown')]
    # The process's handlers stay registered although it never started.
    assert all(re.fullmatch(processing(SHUTDOWN_EVENT, ON_SHUTDOWN), line)
               for line in lines[-2:])


def test_a_service_made_after_a_debug_one_logs_at_info(run_launch):
    """Observed on Jazzy's LaunchService: the level is set by every service, not only debug ones."""
    assert '[DEBUG]' in run_launch([LogInfo(msg='one')], debug=True).output
    output = run_launch([LogInfo(msg='two')]).output
    assert '[DEBUG]' not in output
    assert '[INFO] [launch]: Default logging verbosity is set to INFO' in output


def test_an_unfinished_last_line_is_printed_after_the_exit(ros2, tmp_path):
    """Jazzy (4 of 4 runs, with and without -d): a last line without a newline comes after
    the exit line; whole lines come in order (before the exit line in most runs)."""
    lines = _launch_d(ros2, tmp_path, """
from launch.actions import ExecuteProcess
def generate_launch_description():
    return LaunchDescription([ExecuteProcess(cmd=['sh', '-c', 'echo one; printf two'],
                                             output='screen')])
""")
    exited = _index(lines, r'\[INFO\] \[sh-1\]: process has finished cleanly \[pid \d+\]')
    assert lines.index('[sh-1] one') < lines.index('[sh-1] two')
    assert exited < lines.index('[sh-1] two')
