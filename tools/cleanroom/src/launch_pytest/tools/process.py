"""Wait for a launched process to start, print, or exit (async and `_sync` forms).

Each waits by looking at the process action until the state is reached or
`timeout` seconds passed (None: no limit).  The output ones read the cached
output, so the action needs `cached_output=True`.
"""
from __future__ import annotations

import asyncio
import time
from collections.abc import Callable

from launch import LaunchContext
from launch.actions import ExecuteProcess

POLL_INTERVAL = 0.05


def _started(action: ExecuteProcess) -> bool:
    details = action.process_details
    return details is not None and details.get('pid') is not None


def _exited(action: ExecuteProcess) -> bool:
    return _started(action) and action.return_code is not None


async def _wait(condition: Callable[[], bool], timeout: float | None) -> bool:
    deadline = None if timeout is None else time.monotonic() + timeout
    while not condition():
        if deadline is not None and time.monotonic() >= deadline:
            return condition()
        await asyncio.sleep(POLL_INTERVAL)
    return True


def _wait_sync(condition: Callable[[], bool], timeout: float | None) -> bool:
    deadline = None if timeout is None else time.monotonic() + timeout
    while not condition():
        if deadline is not None and time.monotonic() >= deadline:
            return condition()
        time.sleep(POLL_INTERVAL)
    return True


def _name(action: ExecuteProcess) -> str:
    details = action.process_details
    return str(details['name'] if details else action.name)


def _no_match(action: ExecuteProcess, stream: str) -> str:
    return f'the {stream} of process {_name(action)} did not pass validate_output'


def _stdout_matches(action, validate_output) -> Callable[[], bool]:
    return lambda: bool(validate_output(action.get_stdout()))


def _stderr_matches(action, validate_output) -> Callable[[], bool]:
    return lambda: bool(validate_output(action.get_stderr()))


async def wait_for_start(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                         timeout: float | None = None) -> None:
    """Return once the process has started; TimeoutError after `timeout` seconds."""
    if not await _wait(lambda: _started(execute_process_action), timeout):
        raise TimeoutError(f'process {_name(execute_process_action)} did not start within '
                           f'{timeout} s')


def wait_for_start_sync(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                        timeout: float | None = None) -> None:
    """wait_for_start for a test that is not async."""
    if not _wait_sync(lambda: _started(execute_process_action), timeout):
        raise TimeoutError(f'process {_name(execute_process_action)} did not start within '
                           f'{timeout} s')


async def wait_for_exit(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                        timeout: float | None = None) -> int:
    """Return the exit code once the process exited; TimeoutError after `timeout` seconds."""
    if not await _wait(lambda: _exited(execute_process_action), timeout):
        raise TimeoutError(f'process {_name(execute_process_action)} did not exit within '
                           f'{timeout} s')
    return execute_process_action.return_code


def wait_for_exit_sync(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                       timeout: float | None = None) -> int:
    """wait_for_exit for a test that is not async."""
    if not _wait_sync(lambda: _exited(execute_process_action), timeout):
        raise TimeoutError(f'process {_name(execute_process_action)} did not exit within '
                           f'{timeout} s')
    return execute_process_action.return_code


async def wait_for_output(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                          validate_output: Callable[[str], bool],
                          timeout: float | None = None) -> bool:
    """True once validate_output(all stdout so far) is true; False after `timeout`."""
    return await _wait(_stdout_matches(execute_process_action, validate_output), timeout)


def wait_for_output_sync(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                         validate_output: Callable[[str], bool],
                         timeout: float | None = None) -> bool:
    """wait_for_output for a test that is not async."""
    return _wait_sync(_stdout_matches(execute_process_action, validate_output), timeout)


async def wait_for_stderr(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                          validate_output: Callable[[str], bool],
                          timeout: float | None = None) -> bool:
    """True once validate_output(all stderr so far) is true; False after `timeout`."""
    return await _wait(_stderr_matches(execute_process_action, validate_output), timeout)


def wait_for_stderr_sync(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                         validate_output: Callable[[str], bool],
                         timeout: float | None = None) -> bool:
    """wait_for_stderr for a test that is not async."""
    return _wait_sync(_stderr_matches(execute_process_action, validate_output), timeout)


async def assert_output(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                        validate_output: Callable[[str], bool],
                        timeout: float | None = None) -> None:
    """Fail unless validate_output(stdout) becomes true (checked now when timeout is None)."""
    if not await _wait(_stdout_matches(execute_process_action, validate_output), timeout or 0):
        raise AssertionError(_no_match(execute_process_action, 'stdout'))


def assert_output_sync(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                       validate_output: Callable[[str], bool],
                       timeout: float | None = None) -> None:
    """assert_output for a test that is not async."""
    if not _wait_sync(_stdout_matches(execute_process_action, validate_output), timeout or 0):
        raise AssertionError(_no_match(execute_process_action, 'stdout'))


async def assert_stderr(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                        validate_output: Callable[[str], bool],
                        timeout: float | None = None) -> None:
    """Fail unless validate_output(stderr) becomes true (checked now when timeout is None)."""
    if not await _wait(_stderr_matches(execute_process_action, validate_output), timeout or 0):
        raise AssertionError(_no_match(execute_process_action, 'stderr'))


def assert_stderr_sync(launch_context: LaunchContext, execute_process_action: ExecuteProcess,
                       validate_output: Callable[[str], bool],
                       timeout: float | None = None) -> None:
    """assert_stderr for a test that is not async."""
    if not _wait_sync(_stderr_matches(execute_process_action, validate_output), timeout or 0):
        raise AssertionError(_no_match(execute_process_action, 'stderr'))


def register_event_handler(context: LaunchContext, event_handler) -> None:
    """Register an event handler with a running launch (thread-safe)."""
    loop = context.asyncio_loop
    if loop is None:
        context.register_event_handler(event_handler)
    else:
        loop.call_soon_threadsafe(context.register_event_handler, event_handler)
