"""Path of the launch file being processed, and its folder."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..substitution import Substitution
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


def _current_launch_file_local(context: LaunchContext, key: str, user: str) -> str:
    value = context.get_locals_as_dict().get(key)
    if value is None:
        raise SubstitutionFailure(f'{user} used outside of a launch file (in a script)')
    return str(value)


class ThisLaunchFile(Substitution):
    """The absolute path of the launch file this substitution appears in."""

    def describe(self) -> str:
        """Return 'ThisLaunchFile()'."""
        return 'ThisLaunchFile()'

    def perform(self, context: LaunchContext) -> str:
        """Return the path."""
        return _current_launch_file_local(context, 'current_launch_file_path', 'ThisLaunchFile')


class ThisLaunchFileDir(Substitution):
    """The folder of the launch file this substitution appears in."""

    def describe(self) -> str:
        """Return 'ThisLaunchFileDir()'."""
        return 'ThisLaunchFileDir()'

    def perform(self, context: LaunchContext) -> str:
        """Return the folder."""
        return _current_launch_file_local(context, 'current_launch_file_directory',
                                          'ThisLaunchFileDir')


# Shown in reprs (`ros2 launch -p` prints them) under the module names Jazzy uses.
ThisLaunchFileDir.__module__ = 'launch.substitutions.this_launch_file_dir'
