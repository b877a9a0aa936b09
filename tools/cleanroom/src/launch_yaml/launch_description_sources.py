"""YAMLLaunchDescriptionSource: include a YAML launch file explicitly as YAML."""
from __future__ import annotations

from launch.launch_description_sources import FrontendLaunchDescriptionSource
from launch.some_substitutions_type import SomeSubstitutionsType

from .parser import Parser


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """A launch description read from a YAML launch file."""

    def __init__(self, launch_file_path: SomeSubstitutionsType) -> None:
        super().__init__(launch_file_path, method='interpreted YAML launch file', parser=Parser)
