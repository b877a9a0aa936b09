"""The event that adds a launch description to a running LaunchService."""
from ..event import Event


class IncludeLaunchDescription(Event):
    """Carries a LaunchDescription to visit (LaunchService.include_launch_description)."""

    name = 'launch.events.IncludeLaunchDescription'

    def __init__(self, launch_description: object) -> None:
        self.__launch_description = launch_description

    @property
    def launch_description(self) -> object:
        """The description to include."""
        return self.__launch_description
