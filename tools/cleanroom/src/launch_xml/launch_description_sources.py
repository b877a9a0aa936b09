"""XMLLaunchDescriptionSource: include an XML launch file explicitly as XML."""
from __future__ import annotations

from launch.launch_description_sources import FrontendLaunchDescriptionSource
from launch.some_substitutions_type import SomeSubstitutionsType

from .parser import Parser


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """A launch description read from an XML launch file."""

    def __init__(self, launch_file_path: SomeSubstitutionsType) -> None:
        super().__init__(launch_file_path, method='interpreted XML launch file', parser=Parser)
