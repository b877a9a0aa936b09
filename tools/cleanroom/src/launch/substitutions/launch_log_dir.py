"""The folder this launch writes its log files to."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..logging import launch_config
from ..substitution import Substitution

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class LaunchLogDir(Substitution):
    """The per-launch log folder (the one announced by 'All log files can be found below')."""

    def describe(self) -> str:
        """Return 'LaunchLogDir()'."""
        return 'LaunchLogDir()'

    def perform(self, context: LaunchContext) -> str:
        """Return the folder."""
        return launch_config.log_dir
