"""Shared logic of handlers for events about one action (process start/exit, ...)."""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from ..action import Action
from ..event import Event
from ..event_handler import BaseEventHandler, normalize_entities
from ..launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from ..launch_context import LaunchContext

ActionMatcher = None | Action | Callable[[Action], bool]


def action_matches(target: ActionMatcher, action: object) -> bool:
    """True if `action` is `target`, satisfies the predicate `target`, or target is None."""
    if target is None:
        return True
    if isinstance(target, Action):
        return action is target
    return bool(target(action))


class OnActionEventBase(BaseEventHandler):
    """Handle events of `target_event_cls` whose action matches `action_matcher`.

    `on_event` is either entities to return, or a callable
    `(event, context) -> entities`.
    """

    # The action class the matcher description names, as Jazzy's does (OnProcessExit: ExecuteLocal).
    _described_action_cls = 'Action'

    def __init__(self, *, action_matcher: ActionMatcher, on_event: object,
                 target_event_cls: type[Event], target_action_cls: type[Action] = Action,
                 **kwargs: object) -> None:
        if action_matcher is not None and not isinstance(action_matcher, target_action_cls) \
                and not callable(action_matcher):
            raise TypeError(f"target_action must be a '{target_action_cls.__name__}', "
                            f"a callable or None, got '{type(action_matcher)}'")
        self.__action_matcher = action_matcher
        self.__target_event_cls = target_event_cls
        if callable(on_event) and not isinstance(on_event, LaunchDescriptionEntity):
            self.__callback: Callable | None = on_event
            self.__entities: list[LaunchDescriptionEntity] = []
        else:
            self.__callback = None
            self.__entities = normalize_entities(on_event)
        super().__init__(matcher=self._match, **kwargs)

    def _match(self, event: Event) -> bool:
        return isinstance(event, self.__target_event_cls) and \
            action_matches(self.__action_matcher, getattr(event, 'action', None))

    @property
    def handler_description(self) -> str:
        """What the handler does: the callable as str() shows it, or '<actions>'."""
        if self.__callback is not None:
            return str(self.__callback)
        return '<actions>'

    @property
    def matcher_description(self) -> str:
        """Which events the handler takes, worded as Jazzy's `ros2 launch -p` shows it."""
        text = f'event == {self.__target_event_cls.__name__}'
        if self.__action_matcher is None:
            return text
        return f'{text} and {self._described_action_cls}(event.action)'

    def describe(self) -> tuple[str, list[LaunchDescriptionEntity]]:
        """Return a description and the entities."""
        text, _ = super().describe()
        return (text, list(self.__entities))

    def _call(self, event: Event, context: LaunchContext) -> object:
        assert self.__callback is not None
        return self.__callback(event, context)

    def handle(self, event: Event,
               context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Return the entities, or what the callback returns."""
        super().handle(event, context)
        if self.__callback is not None:
            return normalize_entities(self._call(event, context))
        return self.__entities
