"""LaunchService: runs launch descriptions on an asyncio loop until done."""
from __future__ import annotations

import asyncio
import logging
import signal
import threading
import traceback
from collections.abc import Coroutine, Iterable
from typing import Any

from . import logging as launch_logging
from .event import Event
from .event_handlers.on_include_launch_description import OnIncludeLaunchDescription
from .event_handlers.on_shutdown import OnShutdown
from .events import IncludeLaunchDescription, Shutdown
from .launch_context import LaunchContext
from .launch_description import LaunchDescription
from .launch_description_entity import LaunchDescriptionEntity


def parse_launch_arguments(argv: Iterable[str]) -> list[tuple]:
    """Return the (name, value) pairs of the `name:=value` items of argv."""
    return [tuple(arg.split(':=', 1)) for arg in argv if ':=' in arg]


class LaunchService:
    """Visit launch descriptions, dispatch events, and wait for processes.

    The service runs until it is idle (no events, no pending actions such as
    running processes or timers) when `shutdown_when_idle`, or until a
    Shutdown event.  Whatever ends it, the Shutdown event is handled (so
    OnShutdown cleanups run) and all processes are stopped before run()
    returns.  An exception from an action ends the launch with exit code 1.
    With `debug`, as Jazzy documents it, "asyncio and the logger are set up
    for debug": the launch loggers log at DEBUG (an action's exception shows
    its traceback) and the event loop runs in asyncio's debug mode.
    """

    def __init__(self, *, argv: Iterable[str] | None = None, noninteractive: bool = False,
                 debug: bool = False) -> None:
        self.__argv = list(argv or [])
        self.__debug = debug
        # As Jazzy's: every service sets the level, so a service made after a
        # debug one logs at INFO again.
        launch_logging.launch_config.set_level(logging.DEBUG if debug else logging.INFO)
        self.__logger = launch_logging.get_logger('launch')
        self.__context = LaunchContext(argv=self.__argv, noninteractive=noninteractive)
        for name, value in parse_launch_arguments(self.__argv):
            self.__context.launch_configurations[name] = value
        # The service's own Shutdown handler comes first, so it is the last to run
        # (`ros2 launch -d` shows it as the last OnShutdown of every launch, as in Jazzy).
        self.__context.register_event_handler(OnShutdown(on_shutdown=self.__on_shutdown))
        self.__context.register_event_handler(OnIncludeLaunchDescription())
        self.__pending: set[asyncio.Future] = set()
        self.__shutdown_handled = False
        self.__return_code = 0
        self.__running = False
        self.__sigint_count = 0
        self.__sigterm_count = 0
        self.__loop: asyncio.AbstractEventLoop | None = None
        self.__loop_thread: int | None = None

    @property
    def context(self) -> LaunchContext:
        """The launch context."""
        return self.__context

    @property
    def task(self) -> None:
        """Kept for API compatibility; the service has no single task."""
        return None

    @property
    def event_loop(self) -> asyncio.AbstractEventLoop | None:
        """The event loop of the thread running the service; None when it is not running."""
        return self.__loop

    def emit_event(self, event: Event) -> None:
        """Queue an event (thread-safe)."""
        self.__context.emit_event_sync(event)

    def include_launch_description(self, launch_description: LaunchDescription) -> None:
        """Queue a launch description to be visited (thread-safe)."""
        self.__context.emit_event_sync(IncludeLaunchDescription(launch_description))

    def shutdown(self, force_sync: bool = False) -> Coroutine[Any, Any, None] | None:
        """Ask the launch to shut down; thread-safe.

        From any other thread, or with `force_sync`, the Shutdown event is
        queued at once and None is returned.  Called on the thread of the
        running event loop (from the launch's own coroutines and callbacks)
        without `force_sync`, it returns a coroutine to await, which queues
        the event: as in Jazzy, whose `shutdown` "optionally returns a
        coroutine" (ros2/launch#603).  A loop callback that cannot await, such
        as a signal handler, passes `force_sync=True`.
        """
        loop = self.__loop
        on_loop_thread = loop is not None and self.__loop_thread == threading.get_ident()
        if on_loop_thread and not force_sync:
            return self.__queue_shutdown()
        self.__emit_shutdown()
        return None

    async def __queue_shutdown(self) -> None:
        self.__emit_shutdown()

    def __emit_shutdown(self) -> None:
        self.__context.emit_event_sync(
            Shutdown(reason='LaunchService.shutdown() called', due_to_sigint=False))

    def run(self, *, shutdown_when_idle: bool = True) -> int:
        """Run on a new event loop until done; return 0, or 1 after an error."""
        loop = asyncio.new_event_loop()
        try:
            return loop.run_until_complete(self.run_async(shutdown_when_idle=shutdown_when_idle))
        finally:
            try:
                loop.run_until_complete(loop.shutdown_asyncgens())
            finally:
                loop.close()

    async def run_async(self, *, shutdown_when_idle: bool = True) -> int:
        """Run on the current loop until done; return 0, or 1 after an error."""
        if self.__running:
            raise RuntimeError('LaunchService is already running')
        self.__running = True
        # Logged when the launch starts, not when the service is made: as in Jazzy,
        # after what `ros2 launch` queued (its IncludeLaunchDescription, with `-d`).
        log_dir = launch_logging.launch_config.log_dir
        self.__logger.info(f'All log files can be found below {log_dir}')
        self.__logger.info('Default logging verbosity is set to '
                           f'{logging.getLevelName(launch_logging.launch_config.level)}')
        loop = asyncio.get_running_loop()
        loop_was_debug = loop.get_debug()
        if self.__debug:
            loop.set_debug(True)
        self.__context._set_asyncio_loop(loop)
        self.__loop, self.__loop_thread = loop, threading.get_ident()
        installed = self.__install_signal_handlers(loop)
        try:
            await self.__main_loop(shutdown_when_idle)
        finally:
            loop.set_debug(loop_was_debug)
            for signum in installed:
                loop.remove_signal_handler(signum)
            self.__context._close_spawner()
            self.__context._set_asyncio_loop(None)
            self.__loop = self.__loop_thread = None
            self.__running = False
        return self.__return_code

    # --- main loop ------------------------------------------------------------
    async def __main_loop(self, shutdown_when_idle: bool) -> None:
        context = self.__context
        while True:
            event = context._next_event()
            if event is not None:
                await self.__process_event(event)
                continue
            self.__pending = {f for f in self.__pending if not f.done()}
            if not self.__pending:
                if self.__shutdown_handled:
                    return
                if shutdown_when_idle:
                    context._emit_event(Shutdown(reason='idle'))
                    continue
            waiter = asyncio.ensure_future(context._wait_for_event())
            try:
                await asyncio.wait({waiter, *self.__pending},
                                   return_when=asyncio.FIRST_COMPLETED)
            finally:
                if not waiter.done():
                    waiter.cancel()

    async def __process_event(self, event: Event) -> None:
        context = self.__context
        if isinstance(event, Shutdown) and not context.is_shutdown:
            # A later Shutdown reaches the handlers too, as in Jazzy: OnShutdown
            # handlers run again (processes are not signalled twice).
            context._set_is_shutdown(True)
        # What Jazzy logs at DEBUG (`ros2 launch -d`): the event, then each handler taking it.
        self.__logger.debug(f"processing event: '{event!r}'")
        for handler in list(context._event_handlers):
            if handler not in context._event_handlers:
                continue  # unregistered by an earlier handler for this event
            try:
                if not handler.matches(event):
                    continue
                self.__logger.debug(f"processing event: '{event!r}' ✓ '{handler!r}'")
                context._push_locals()
                try:
                    entities = handler.handle(event, context)
                    if entities:
                        self.__visit_all(LaunchDescription(entities))
                finally:
                    context._pop_locals()
            except Exception as exc:  # noqa: BLE001 - any failure ends the launch cleanly
                self.__fail(exc)
        await asyncio.sleep(0)  # let I/O and timers run between events

    def __visit_all(self, entity: LaunchDescriptionEntity) -> None:
        """Visit depth first; collect futures of actions still running."""
        sub_entities = entity.visit(self.__context)
        future = entity.get_asyncio_future()
        if future is not None and not future.done():
            self.__pending.add(future)
        for sub_entity in sub_entities or []:
            self.__visit_all(sub_entity)

    def __on_shutdown(self, event: Event, context: LaunchContext) -> None:
        """Registered first, so it runs after every other Shutdown handler: then the
        launch may end once nothing is pending (context.is_shutdown is set before any)."""
        self.__shutdown_handled = True

    def __fail(self, exc: BaseException) -> None:
        self.__logger.debug('An exception was raised in an async action/event')
        self.__logger.debug(''.join(traceback.format_exception(exc)))
        self.__logger.error(f'Caught exception in launch (see debug for traceback): {exc}')
        self.__return_code = 1
        if not self.__context.is_shutdown:
            self.__context._emit_event(Shutdown(reason=f'exception: {exc}'))

    # --- signals --------------------------------------------------------------
    def __install_signal_handlers(self, loop: asyncio.AbstractEventLoop) -> list[int]:
        if threading.current_thread() is not threading.main_thread():
            return []  # signals can only be handled on the main thread
        installed = []
        for signum, handler in ((signal.SIGINT, self.__on_sigint),
                                (signal.SIGTERM, self.__on_sigterm)):
            try:
                loop.add_signal_handler(signum, handler)
                installed.append(signum)
            except (ValueError, RuntimeError, NotImplementedError):
                pass
        return installed

    def __on_sigint(self) -> None:
        self.__sigint_count += 1
        if self.__sigint_count > 1:
            self.__logger.warning('user interrupted with ctrl-c (SIGINT) again, ignoring...')
            return
        self.__logger.warning('user interrupted with ctrl-c (SIGINT)')
        # As in Jazzy: a terminal's Ctrl-C reached every process of the group already,
        # so processes only get SIGINT from us when the launch is `noninteractive`.
        self.__context.emit_event_sync(Shutdown(reason='ctrl-c (SIGINT)', due_to_sigint=True))

    def __on_sigterm(self) -> None:
        self.__sigterm_count += 1
        if self.__sigterm_count > 1:
            self.__logger.warning('received SIGTERM again, ignoring...')
            return
        self.__logger.warning('received SIGTERM, shutting down')
        self.__context.emit_event_sync(Shutdown(reason='SIGTERM', due_to_sigint=False))
