"""Group actions, optionally in their own scope of configurations and environment."""
from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..action import Action
from ..launch_description_entity import LaunchDescriptionEntity
from .launch_configuration_actions import SetLaunchConfiguration
from .scope_actions import (
    PopEnvironment,
    PopLaunchConfigurations,
    PushEnvironment,
    PushLaunchConfigurations,
    ResetLaunchConfigurations,
)

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class GroupAction(Action):
    """Visit `actions` together, under the group's condition.

    With `scoped=True` (default) launch configurations and the environment
    changed inside the group are restored afterwards.  `forwarding=False`
    starts the group with only `launch_configurations`; otherwise those are
    set on top of the current ones.
    """

    def __init__(self, actions: Iterable[Action], *, scoped: bool = True,
                 forwarding: bool = True,
                 launch_configurations: (dict[SomeSubstitutionsType, SomeSubstitutionsType]
                                         | None) = None,
                 **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__actions = list(actions)
        self.__scoped = scoped
        self.__forwarding = forwarding
        self.__launch_configurations = dict(launch_configurations or {})

    @property
    def actions(self) -> list[Action]:
        """The grouped actions."""
        return self.__actions

    def describe(self) -> str:
        """Return a description."""
        return f'GroupAction(scoped={self.__scoped}, forwarding={self.__forwarding})'

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """The entities visited for this group, scoping actions included."""
        if not self.__scoped:
            return [*self.__set_configurations(), *self.__actions]
        if self.__forwarding:
            inner: list[LaunchDescriptionEntity] = [*self.__set_configurations(), *self.__actions]
        else:
            inner = [ResetLaunchConfigurations(self.__launch_configurations), *self.__actions]
        return [PushLaunchConfigurations(), PushEnvironment(), *inner,
                PopEnvironment(), PopLaunchConfigurations()]

    def __set_configurations(self) -> list[Action]:
        return [SetLaunchConfiguration(k, v) for k, v in self.__launch_configurations.items()]

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """The grouped actions."""
        return list(self.__actions)

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        """Return the actions wrapped in the scope."""
        return self.get_sub_entities()
