"""Push/pop/reset of launch configurations and environment: the scoping primitives."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..action import Action
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class PushLaunchConfigurations(Action):
    """Save a copy of the launch configurations (GroupAction's scope start)."""

    def execute(self, context: LaunchContext) -> None:
        """Push."""
        context._push_launch_configurations()


class PopLaunchConfigurations(Action):
    """Restore the launch configurations saved by the last push."""

    def execute(self, context: LaunchContext) -> None:
        """Pop."""
        context._pop_launch_configurations()


class ResetLaunchConfigurations(Action):
    """Clear the launch configurations, then set `launch_configurations` if given.

    The new values are computed before clearing, so they may refer to the
    configurations being cleared.
    """

    def __init__(self, launch_configurations: (dict[SomeSubstitutionsType, SomeSubstitutionsType]
                                               | None) = None, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__launch_configurations = launch_configurations

    def execute(self, context: LaunchContext) -> None:
        """Reset."""
        values: dict[str, str] = {}
        for name, value in (self.__launch_configurations or {}).items():
            values[perform_substitutions(context, normalize_to_list_of_substitutions(name))] = \
                perform_substitutions(context, normalize_to_list_of_substitutions(value))
        context.launch_configurations.clear()
        context.launch_configurations.update(values)


class PushEnvironment(Action):
    """Save a copy of the process environment (GroupAction's scope start)."""

    def execute(self, context: LaunchContext) -> None:
        """Push."""
        context._push_environment()


class PopEnvironment(Action):
    """Restore the environment saved by the last push."""

    def execute(self, context: LaunchContext) -> None:
        """Pop."""
        context._pop_environment()


class ResetEnvironment(Action):
    """Reset the process environment to what it was when the launch started."""

    def execute(self, context: LaunchContext) -> None:
        """Reset."""
        context._reset_environment()


class PushLocals(Action):
    """Save the context locals (used around included launch descriptions)."""

    def __init__(self, extensions: dict | None = None, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__extensions = extensions or {}

    def execute(self, context: LaunchContext) -> None:
        """Push, then add the extensions."""
        context._push_locals()
        context.extend_locals(self.__extensions)


class PopLocals(Action):
    """Restore the locals saved by the last PushLocals."""

    def execute(self, context: LaunchContext) -> None:
        """Pop."""
        context._pop_locals()


# Shown in reprs (`ros2 launch -p` prints them) under the module names Jazzy uses.
PushLaunchConfigurations.__module__ = 'launch.actions.push_launch_configurations'
PopLaunchConfigurations.__module__ = 'launch.actions.pop_launch_configurations'
ResetLaunchConfigurations.__module__ = 'launch.actions.reset_launch_configurations'
PushEnvironment.__module__ = 'launch.actions.push_environment'
PopEnvironment.__module__ = 'launch.actions.pop_environment'
ResetEnvironment.__module__ = 'launch.actions.reset_environment'
