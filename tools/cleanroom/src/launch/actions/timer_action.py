"""Visit actions after a delay."""
from __future__ import annotations

import asyncio
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

from ..action import Action
from ..conditions.evaluate_condition_expression import evaluate_condition_expression
from ..event_handler import EventHandler
from ..events import Shutdown, TimerEvent
from ..launch_description_entity import LaunchDescriptionEntity
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .opaque_function import OpaqueFunction
from .scope_actions import (
    PopEnvironment,
    PopLaunchConfigurations,
    PopLocals,
    PushEnvironment,
    PushLaunchConfigurations,
    PushLocals,
)

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class _RestoreScope(Action):
    """Put back the configurations a timer saw when it was started.

    The environment is not restored: as in Jazzy, the timer's actions see the
    environment of when it fires (frontends golden 34_xml_executable_timer).
    """

    def __init__(self, configurations: dict) -> None:
        super().__init__()
        self.__configurations = configurations

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.clear()
        context.launch_configurations.update(self.__configurations)


class TimerAction(Action):
    """After `period` seconds, visit `actions` as if they were where the timer is.

    The launch configurations and locals (e.g. the current launch file) of
    the timer's scope are saved when it starts and restored for its actions
    (the environment is the one of when it fires) (e.g. a namespace
    pushed in an enclosing group still applies).  The timer is cancelled on
    shutdown unless `cancel_on_shutdown=False`.
    """

    def __init__(self, *, period: float | SomeSubstitutionsType,
                 actions: Iterable[LaunchDescriptionEntity],
                 cancel_on_shutdown: bool | SomeSubstitutionsType = True,
                 **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__period = float(period) if isinstance(period, (int, float)) \
            else normalize_to_list_of_substitutions(period)
        self.__actions = list(actions)
        self.__cancel_on_shutdown = cancel_on_shutdown
        self.__future: asyncio.Future | None = None
        self.__handle: asyncio.TimerHandle | None = None
        self.__canceled = False

    @property
    def period(self) -> float | list:
        """The delay in seconds (or its substitutions)."""
        return self.__period

    @property
    def actions(self) -> list[LaunchDescriptionEntity]:
        """The actions run after the delay."""
        return self.__actions

    def describe(self) -> str:
        """Return a description."""
        return f'TimerAction(period={self.__period})'

    def describe_conditional_sub_entities(
            self) -> list[tuple[str, Sequence[LaunchDescriptionEntity]]]:
        """The actions, after the period."""
        return [(f'{self.__period} seconds pass', self.__actions)]

    def get_asyncio_future(self) -> asyncio.Future | None:
        """Done when the timer fired or was cancelled."""
        return self.__future

    def cancel(self) -> None:
        """Cancel the timer; its actions will not run."""
        self.__canceled = True
        if self.__handle is not None:
            self.__handle.cancel()
        if self.__future is not None and not self.__future.done():
            self.__future.set_result(None)

    def __cancel_in(self, context: LaunchContext, handler: EventHandler) -> None:
        if self.__future is not None and not self.__future.done():
            self.cancel()
            if handler in context._event_handlers:
                context.unregister_event_handler(handler)

    def execute(self, context: LaunchContext) -> None:
        """Start the timer."""
        period = self.__period if isinstance(self.__period, float) \
            else float(perform_substitutions(context, self.__period))
        loop = context.asyncio_loop
        assert loop is not None, 'TimerAction needs a running LaunchService'
        self.__future = loop.create_future()
        if self.__canceled:
            self.__future.set_result(None)
            return None
        saved = (dict(context.launch_configurations),)
        entities = [PushLaunchConfigurations(), PushEnvironment(),
                    PushLocals(context.get_locals_as_dict()), _RestoreScope(*saved),
                    *self.__actions, PopLocals(), PopEnvironment(), PopLaunchConfigurations()]
        handler = EventHandler(
            matcher=lambda event: isinstance(event, TimerEvent) and event.timer_action is self,
            entities=entities, handle_once=True)
        context.register_event_handler(handler)

        cancel = self.__cancel_on_shutdown
        if not isinstance(cancel, bool):
            cancel = evaluate_condition_expression(
                context, normalize_to_list_of_substitutions(cancel))
        if cancel:
            context.register_event_handler(EventHandler(  # an EventHandler, as Jazzy's
                matcher=lambda event: isinstance(event, Shutdown),
                entities=OpaqueFunction(function=lambda ctx: self.__cancel_in(ctx, handler))))

        def fire() -> None:
            if self.__canceled:
                return
            context._emit_event(TimerEvent(timer_action=self))
            if not self.__future.done():
                self.__future.set_result(None)
        self.__handle = loop.call_later(period, fire)
        return None
