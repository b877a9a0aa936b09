"""Run a coroutine function on the launch's loop."""
from __future__ import annotations

import asyncio
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from ..action import Action
from ..event_handlers.on_shutdown import OnShutdown

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class OpaqueCoroutine(Action):
    """Schedule `coroutine(context, *args, **kwargs)` (or without context if
    `ignore_context`); the launch waits for it, and cancels it on shutdown."""

    def __init__(self, *, coroutine: Callable[..., Any], args: Iterable[Any] | None = None,
                 kwargs: dict[str, Any] | None = None, ignore_context: bool = False,
                 **left_over_kwargs: object) -> None:
        super().__init__(**left_over_kwargs)
        if not asyncio.iscoroutinefunction(coroutine):
            raise TypeError(f"OpaqueCoroutine expected a coroutine function for 'coroutine', "
                            f"got '{type(coroutine)}'")
        self.__coroutine = coroutine
        self.__args = list(args or [])
        self.__kwargs = dict(kwargs or {})
        self.__ignore_context = ignore_context
        self.__task: asyncio.Task | None = None

    def describe(self) -> str:
        """Return a description."""
        return f"OpaqueCoroutine({getattr(self.__coroutine, '__name__', '?')})"

    def get_asyncio_future(self) -> asyncio.Future | None:
        """The task running the coroutine."""
        return self.__task

    def execute(self, context: LaunchContext) -> None:
        """Start the coroutine and cancel it when the launch shuts down."""
        args = self.__args if self.__ignore_context else [context, *self.__args]
        loop = context.asyncio_loop
        assert loop is not None, 'OpaqueCoroutine needs a running LaunchService'
        self.__task = loop.create_task(self.__coroutine(*args, **self.__kwargs))
        context.register_event_handler(OnShutdown(on_shutdown=self.__cancel, handle_once=True))
        return None

    def __cancel(self, event: object, context: LaunchContext) -> None:
        if self.__task is not None:
            self.__task.cancel()
