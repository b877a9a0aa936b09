"""Run a Python function with the launch context; it may return more entities."""
from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from ..action import Action
from ..event_handler import normalize_entities
from ..launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class OpaqueFunction(Action):
    """Call `function(context, *args, **kwargs)` and visit what it returns."""

    def __init__(self, *, function: Callable[..., Iterable[LaunchDescriptionEntity] | None],
                 args: Iterable[Any] | None = None, kwargs: dict[str, Any] | None = None,
                 **left_over_kwargs: object) -> None:
        super().__init__(**left_over_kwargs)
        if not callable(function):
            raise TypeError(f"OpaqueFunction expected a callable for 'function', "
                            f"got '{type(function)}'")
        self.__function = function
        self.__args = list(args or [])
        self.__kwargs = dict(kwargs or {})

    @property
    def function(self) -> Callable:
        """The function."""
        return self.__function

    def describe(self) -> str:
        """Return a description."""
        return f"OpaqueFunction({getattr(self.__function, '__name__', '?')})"

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        """Call the function."""
        return normalize_entities(self.__function(context, *self.__args, **self.__kwargs))
