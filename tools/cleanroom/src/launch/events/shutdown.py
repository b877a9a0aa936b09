"""The event that ends a launch."""

from ..event import Event


class Shutdown(Event):
    """Ask the LaunchService to stop all processes and finish.

    `due_to_sigint` tells processes whether the user pressed Ctrl-C (they may
    have received SIGINT from the terminal already).
    """

    name = 'launch.events.Shutdown'

    def __init__(self, *, reason: str = 'reason not given', due_to_sigint: bool = False) -> None:
        self.__reason = reason
        self.__due_to_sigint = due_to_sigint

    @property
    def reason(self) -> str:
        """Why the launch shuts down."""
        return self.__reason

    @property
    def due_to_sigint(self) -> bool:
        """True when caused by SIGINT to the launch."""
        return self.__due_to_sigint
