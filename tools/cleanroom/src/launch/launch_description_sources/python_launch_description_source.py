"""A LaunchDescription loaded from a Python launch file."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..launch_description import LaunchDescription
from ..launch_description_source import LaunchDescriptionSource
from .python_launch_file_utilities import get_launch_description_from_python_launch_file

if TYPE_CHECKING:
    from ..some_substitutions_type import SomeSubstitutionsType


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    """Load `launch_file_path` (text or substitutions) as a Python launch file."""

    def __init__(self, launch_file_path: SomeSubstitutionsType) -> None:
        super().__init__(None, launch_file_path, 'interpreted python launch file')

    def _get_launch_description(self, location: str) -> LaunchDescription:
        return get_launch_description_from_python_launch_file(location)
