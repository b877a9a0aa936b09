"""The state a launch runs in: launch configurations, environment, locals, events."""
from __future__ import annotations

import asyncio
import collections
import itertools
import os
import threading
from collections.abc import Callable, Iterable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

from .event import Event
from .event_handler import BaseEventHandler
from .logging import get_logger

#: The N of `name-N`, counted across every launch of this Python process.
_PROCESS_NUMBERS = itertools.count(1)

_SPAWNER_THREADS = 1


class _Locals:
    """Attribute access to the current locals, e.g. `context.locals.event`."""

    def __init__(self, values: dict[str, Any]) -> None:
        object.__setattr__(self, '_values', values)

    def __getattr__(self, name: str) -> Any:
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(f"context.locals does not contain attribute '{name}', "
                                 f'it contains: [{", ".join(self._values)}]') from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError('context.locals is read-only; use context.extend_locals()')


class LaunchContext:
    """Everything actions share while a LaunchService runs.

    Launch configurations and the environment given to processes are plain
    dicts; GroupAction(scoped=True) pushes and pops copies of both, while
    IncludeLaunchDescription does not (as in ROS 2 Jazzy).  The environment
    starts as a copy of os.environ so that launching never changes the
    launching process's own environment.
    """

    def __init__(self, *, argv: Iterable[str] | None = None,
                 noninteractive: bool = False) -> None:
        self.__argv = list(argv or [])
        self.__noninteractive = noninteractive
        self._event_handlers: list[BaseEventHandler] = []
        self.__events: collections.deque = collections.deque()
        self.__wakeup: asyncio.Event | None = None
        self.__loop: asyncio.AbstractEventLoop | None = None
        self.__loop_thread: int | None = None
        self.__globals: dict[str, Any] = {}
        self.__locals_stack: list[dict[str, Any]] = []
        self.__locals: dict[str, Any] = {}
        self.__configurations_stack: list[dict[str, Any]] = []
        self.__launch_configurations: dict[str, Any] = {}
        self.__initial_environment = dict(os.environ)
        self.__environment_stack: list[dict[str, str]] = []
        self.__environment: dict[str, str] = dict(self.__initial_environment)
        self.__is_shutdown = False
        self.__spawner: ThreadPoolExecutor | None = None

    # --- plain properties -------------------------------------------------
    @property
    def argv(self) -> list[str]:
        """The arguments given to the LaunchService."""
        return self.__argv

    @property
    def noninteractive(self) -> bool:
        """True when no terminal user can press Ctrl-C (SIGINT is always forwarded then)."""
        return self.__noninteractive

    @property
    def is_shutdown(self) -> bool:
        """True once the Shutdown event has been handled."""
        return self.__is_shutdown

    def _set_is_shutdown(self, state: bool) -> None:
        self.__is_shutdown = state

    @property
    def asyncio_loop(self) -> asyncio.AbstractEventLoop | None:
        """The event loop the LaunchService runs on (set before anything executes)."""
        return self.__loop

    def _set_asyncio_loop(self, loop: asyncio.AbstractEventLoop | None) -> None:
        self.__loop = loop
        self.__loop_thread = threading.get_ident() if loop is not None else None
        self.__wakeup = asyncio.Event() if loop is not None else None
        if self.__events and self.__wakeup is not None:
            self.__wakeup.set()

    def _run_in_spawner(self, function: Callable[[], Any]) -> asyncio.Future:
        """Run `function` (a process start) on the launch's spawner thread.

        One thread: processes start one after the other in the order the launch
        reaches them, so their ProcessStarted events, "process started" lines and
        launch_testing's proc_info come in that order, as in Jazzy (several
        threads overlapped the fork/execs, a few ms each, and shuffled the
        order).  The thread lives until the LaunchService ends because a child's
        death signal (PR_SET_PDEATHSIG) fires when the thread that started it ends.
        """
        assert self.__loop is not None, 'processes can only be started by a running launch'
        if self.__spawner is None:
            self.__spawner = ThreadPoolExecutor(max_workers=_SPAWNER_THREADS,
                                                thread_name_prefix='launch-spawner')
        return self.__loop.run_in_executor(self.__spawner, function)

    def _close_spawner(self) -> None:
        if self.__spawner is not None:
            self.__spawner.shutdown(wait=True)
            self.__spawner = None

    def _allocate_process_number(self) -> int:
        """Next N of the `name-N` process names.  As in Jazzy, one count for the whole
        Python process: a second LaunchService in it (launch_pytest, launch_testing)
        goes on from where the first stopped (a-1, b-2, then a-3, b-4)."""
        return next(_PROCESS_NUMBERS)  # one C call: no lock needed

    # --- locals and globals -----------------------------------------------
    @property
    def locals(self) -> _Locals:
        """Read-only attribute view of the current locals."""
        return _Locals(self.__locals)

    def extend_locals(self, extensions: dict[str, Any]) -> None:
        """Add or replace locals in the current scope."""
        self.__locals.update(extensions)

    def get_locals_as_dict(self) -> dict[str, Any]:
        """Return a copy of the current locals."""
        return dict(self.__locals)

    def _push_locals(self) -> None:
        self.__locals_stack.append(dict(self.__locals))

    def _pop_locals(self) -> None:
        if not self.__locals_stack:
            raise RuntimeError('locals stack unexpectedly empty')
        self.__locals = self.__locals_stack.pop()

    def extend_globals(self, extensions: dict[str, Any]) -> None:
        """Add globals, visible to all scopes."""
        self.__globals.update(extensions)

    def get_globals(self) -> dict[str, Any]:
        """Return the globals dict."""
        return self.__globals

    # --- launch configurations --------------------------------------------
    @property
    def launch_configurations(self) -> dict[str, Any]:
        """The launch configurations of the current scope (a mutable dict)."""
        return self.__launch_configurations

    def _push_launch_configurations(self) -> None:
        self.__configurations_stack.append(dict(self.__launch_configurations))

    def _pop_launch_configurations(self) -> None:
        if not self.__configurations_stack:
            raise RuntimeError('launch configurations stack unexpectedly empty')
        self.__launch_configurations = self.__configurations_stack.pop()

    # --- environment ------------------------------------------------------
    @property
    def environment(self) -> dict[str, str]:
        """The environment processes get, in the current scope (a mutable dict)."""
        return self.__environment

    def _push_environment(self) -> None:
        self.__environment_stack.append(dict(self.__environment))

    def _pop_environment(self) -> None:
        if not self.__environment_stack:
            raise RuntimeError('environment stack unexpectedly empty')
        self.__environment = self.__environment_stack.pop()

    def _reset_environment(self) -> None:
        self.__environment = dict(self.__initial_environment)

    # --- events -------------------------------------------------------------
    def register_event_handler(self, event_handler: BaseEventHandler,
                               append: bool = False) -> None:
        """Register a handler; newest first unless `append`."""
        if append:
            self._event_handlers.append(event_handler)
        else:
            self._event_handlers.insert(0, event_handler)

    def unregister_event_handler(self, event_handler: BaseEventHandler) -> None:
        """Remove a handler; ValueError if it is not registered."""
        self._event_handlers.remove(event_handler)

    def would_handle_event(self, event: Event) -> bool:
        """True if a registered handler matches `event`."""
        return any(handler.matches(event) for handler in self._event_handlers)

    def emit_event_sync(self, event: Event) -> None:
        """Queue an event; safe to call from any thread."""
        self._emit_event(event, 'emitting event synchronously')

    async def emit_event(self, event: Event) -> None:
        """Queue an event (coroutine form)."""
        self._emit_event(event)

    def _emit_event(self, event: Event, wording: str = 'emitting event') -> None:
        """Queue `event`, logged at DEBUG as Jazzy's `ros2 launch -d` shows it.

        Jazzy logs its coroutine `emit_event` as 'emitting event' and
        `emit_event_sync` as 'emitting event synchronously'; the clean room's
        loop callbacks (process started or exited, timers, idle shutdown) call
        this directly with the default wording, where Jazzy awaits emit_event.
        """
        get_logger('launch.launch_context').debug(f"{wording}: '{event.name}'")
        self.__events.append(event)
        loop, wakeup = self.__loop, self.__wakeup
        if loop is None or wakeup is None:
            return
        if threading.get_ident() == self.__loop_thread:
            wakeup.set()
        else:
            try:
                loop.call_soon_threadsafe(wakeup.set)
            except RuntimeError:  # loop closed: the event is dropped with the launch
                pass

    def _next_event(self) -> Event | None:
        return self.__events.popleft() if self.__events else None

    def _has_events(self) -> bool:
        return bool(self.__events)

    async def _wait_for_event(self) -> None:
        assert self.__wakeup is not None
        await self.__wakeup.wait()
        self.__wakeup.clear()

    # --- substitutions --------------------------------------------------------
    def perform_substitution(self, substitution: Any) -> str:
        """Perform one substitution in this context."""
        return substitution.perform(self)
