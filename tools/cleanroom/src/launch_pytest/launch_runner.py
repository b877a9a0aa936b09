"""Run a launch description on its own thread and event loop while tests run."""
from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable, Coroutine

import launch
from launch_testing.actions import ReadyToTest
from launch_testing.actions.ready_to_test import add_ready_callback

READY_TIMEOUT = 120.0
STOP_TIMEOUT = 60.0

_RUNNERS: dict[int, LaunchRunner] = {}


def description_of(value: object, function: Callable) -> launch.LaunchDescription:
    """The LaunchDescription a launch fixture gave (alone, or first of a sequence)."""
    description = value[0] if isinstance(value, (list, tuple)) and value else value
    if not isinstance(description, launch.LaunchDescription):
        raise TypeError(
            f"launch_pytest fixture '{function.__name__}' "
            f"({function.__code__.co_filename}:{function.__code__.co_firstlineno}) must return "
            'a launch.LaunchDescription or a sequence whose first item is one, not '
            f'{type(value).__name__}')
    return description


def register(value: object, runner: LaunchRunner) -> None:
    """Remember the runner of a fixture value, for launch_service / launch_context."""
    _RUNNERS[id(value)] = runner


def unregister(value: object) -> None:
    """Forget the runner of a fixture value."""
    _RUNNERS.pop(id(value), None)


def runner_of(value: object) -> LaunchRunner | None:
    """The running launch of a fixture value, if any."""
    return _RUNNERS.get(id(value))


class LaunchRunner:
    """A LaunchService on a background thread; tests wait for ReadyToTest, then run."""

    def __init__(self, description: launch.LaunchDescription) -> None:
        if not any(isinstance(e, ReadyToTest) for e in description.entities):
            description.add_action(ReadyToTest())  # as documented: appended when missing
        self.service = launch.LaunchService()
        self.ready = threading.Event()
        self.started = threading.Event()
        self.finished = threading.Event()
        self.return_code: int | None = None
        self.loop = asyncio.new_event_loop()
        add_ready_callback(self.service.context, self.ready.set)
        self.service.include_launch_description(description)
        self._thread = threading.Thread(target=self._run, name='launch_pytest-launch',
                                        daemon=True)

    @property
    def context(self) -> launch.LaunchContext:
        """The launch context of the running launch."""
        return self.service.context

    def start(self) -> None:
        """Start the launch on its thread; return once the service runs (as in Jazzy, its
        first log lines belong to the fixture's setup, not to the first test)."""
        self._thread.start()
        self.started.wait(READY_TIMEOUT)

    def _run(self) -> None:
        asyncio.set_event_loop(self.loop)
        try:
            self.return_code = self.loop.run_until_complete(self._serve())
        finally:
            tasks = [t for t in asyncio.all_tasks(self.loop) if not t.done()]
            for task in tasks:
                task.cancel()
            if tasks:
                self.loop.run_until_complete(asyncio.gather(*tasks, return_exceptions=True))
            self.loop.close()
            self.started.set()
            self.finished.set()

    async def _serve(self) -> int:
        service = asyncio.ensure_future(self.service.run_async(shutdown_when_idle=False))
        await asyncio.sleep(0)  # the service's first step ran: it logged where its logs go
        self.started.set()
        return await service

    def wait_until_ready(self, timeout: float = READY_TIMEOUT) -> None:
        """Block until ReadyToTest ran; fail if the launch ended or took too long."""
        for _ in range(int(timeout * 10)):
            if self.ready.wait(0.1):
                return
            if self.finished.is_set():
                raise RuntimeError(
                    f'the launch ended (exit code {self.return_code}) before ReadyToTest')
        raise TimeoutError(f'the launch did not reach ReadyToTest within {timeout} s')

    def run_coroutine(self, coroutine: Coroutine) -> object:
        """Run a test coroutine on the launch's event loop, as launch_pytest does."""
        if self.finished.is_set():
            return asyncio.run(coroutine)
        future = asyncio.run_coroutine_threadsafe(coroutine, self.loop)
        try:
            return future.result()
        except BaseException:
            future.cancel()
            raise

    def stop(self, timeout: float = STOP_TIMEOUT) -> None:
        """Shut the launch down and wait until every process it started has exited."""
        if not self._thread.is_alive():
            return
        self.service.shutdown()
        self._thread.join(timeout)
        if self._thread.is_alive():
            raise RuntimeError(f'the launch did not shut down within {timeout} s')
