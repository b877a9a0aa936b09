"""Set or unset a launch configuration in the current scope."""
from __future__ import annotations

from collections.abc import MutableMapping
from typing import TYPE_CHECKING

from ._scoped_store_actions import SetInStore, UnsetInStore

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class SetLaunchConfiguration(SetInStore):
    """Set launch configuration `name` to `value` (both may be substitutions)."""

    def describe(self) -> str:
        """Return a description."""
        return (f"SetLaunchConfiguration({' + '.join(s.describe() for s in self.name)}, "
                f"{' + '.join(s.describe() for s in self.value)})")

    def _store(self, context: LaunchContext) -> MutableMapping[str, str]:
        return context.launch_configurations


class UnsetLaunchConfiguration(UnsetInStore):
    """Remove launch configuration `name` from the current scope (if set)."""

    def _store(self, context: LaunchContext) -> MutableMapping[str, str]:
        return context.launch_configurations


# Shown in reprs (`ros2 launch -p` prints them) under the module names Jazzy uses.
SetLaunchConfiguration.__module__ = 'launch.actions.set_launch_configuration'
UnsetLaunchConfiguration.__module__ = 'launch.actions.unset_launch_configuration'
