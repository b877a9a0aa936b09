"""LaunchService.shutdown() and event_loop, used by code that runs a launch itself."""
from __future__ import annotations

import asyncio
import inspect
import threading
from collections.abc import Awaitable, Callable

from launch import LaunchDescription, LaunchService
from launch.actions import ExecuteProcess, OpaqueFunction, RegisterEventHandler
from launch.event import Event
from launch.event_handler import EventHandler
from launch.event_handlers import OnProcessStart, OnShutdown


class Marker(Event):
    """An event emitted after a shutdown() call: once it is handled, so is anything before it."""

    name = 'test.Marker'


class Probe:
    """A launch of one sleeping process that records what the service handled, in order."""

    def __init__(self) -> None:
        self.handled: list[str] = []
        self.started = threading.Event()
        sleeper = ExecuteProcess(cmd=['sleep', '30'], name='sleeper')
        self.service = LaunchService()
        self.service.include_launch_description(LaunchDescription([
            sleeper,
            RegisterEventHandler(OnProcessStart(target_action=sleeper,
                                                on_start=lambda *_: self.started.set())),
            RegisterEventHandler(OnShutdown(
                on_shutdown=lambda *_: self.handled.append('shutdown'))),
            RegisterEventHandler(EventHandler(
                matcher=lambda event: isinstance(event, Marker),
                entities=[OpaqueFunction(function=lambda _: self.handled.append('marker'))])),
        ]))

    async def until_started(self) -> None:
        while not self.started.is_set():
            await asyncio.sleep(0.01)

    async def until_handled(self, what: str) -> None:
        while what not in self.handled:
            await asyncio.sleep(0.01)

    def run_with(self, on_loop: Callable[[Probe], Awaitable[object]]) -> tuple[int, object]:
        """Run the launch and, on the same event loop, the coroutine `on_loop(self)`."""
        async def main() -> tuple[int, object]:
            launch = asyncio.ensure_future(self.service.run_async())
            result = await on_loop(self)
            return await launch, result

        return asyncio.run(main())


def test_event_loop_is_the_running_loop_and_none_outside_a_run():
    probe = Probe()
    assert probe.service.event_loop is None

    async def look(probe: Probe) -> bool:
        await probe.until_started()
        running = probe.service.event_loop is asyncio.get_running_loop()
        probe.service.shutdown(force_sync=True)
        return running

    assert probe.run_with(look) == (0, True)
    assert probe.service.event_loop is None


def test_on_the_loop_shutdown_returns_a_coroutine_that_shuts_down_when_awaited():
    async def stop(probe: Probe) -> list[str]:
        await probe.until_started()
        pending = probe.service.shutdown()
        assert inspect.iscoroutine(pending)
        probe.service.emit_event(Marker())
        await probe.until_handled('marker')
        before_await = list(probe.handled)  # the marker came after: no shutdown queued
        await pending
        return before_await

    probe = Probe()
    assert probe.run_with(stop) == (0, ['marker'])
    assert probe.handled == ['marker', 'shutdown']


def test_on_the_loop_force_sync_shuts_down_at_once():
    async def stop(probe: Probe) -> object:
        await probe.until_started()
        return probe.service.shutdown(force_sync=True)

    probe = Probe()
    assert probe.run_with(stop) == (0, None)
    assert probe.handled == ['shutdown']


def test_from_another_thread_shutdown_returns_none_and_shuts_down():
    async def stop_from_a_thread(probe: Probe) -> list:
        await probe.until_started()
        returned = []
        thread = threading.Thread(target=lambda: returned.append(probe.service.shutdown()))
        thread.start()
        await asyncio.get_running_loop().run_in_executor(None, thread.join)
        return returned

    probe = Probe()
    assert probe.run_with(stop_from_a_thread) == (0, [None])
    assert probe.handled == ['shutdown']


def test_process_numbers_go_on_across_launch_services_of_one_python_process():
    """As Jazzy (observed: a-1, b-2 in a first LaunchService, then a-3, b-4 in a second
    one, c-5 in a third): the N of `name-N` counts every process this Python process
    launched, so two launches of a launch_pytest session never share a process name."""
    names = []

    def run(*launched: str) -> None:
        service = LaunchService()
        service.include_launch_description(LaunchDescription([
            ExecuteProcess(cmd=['true'], name=name) for name in launched] + [
            RegisterEventHandler(OnProcessStart(
                on_start=lambda event, _: names.append(event.action.process_details['name'])))]))
        assert service.run() == 0

    run('a', 'b')
    run('a', 'b')
    numbers = {name: int(name.rsplit('-', 1)[1]) for name in names}
    first = min(numbers.values())
    assert sorted(numbers.values()) == [first, first + 1, first + 2, first + 3], names
    assert {name.rsplit('-', 1)[0] for name in names if numbers[name] >= first + 2} == {'a', 'b'}
