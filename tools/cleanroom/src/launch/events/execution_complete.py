"""The event emitted when an action has finished."""
from ..event import Event


class ExecutionComplete(Event):
    """Emitted after an action's execute() (or when its future completes)."""

    name = 'launch.events.ExecutionComplete'

    def __init__(self, *, action: object) -> None:
        self.__action = action

    @property
    def action(self) -> object:
        """The action that completed."""
        return self.__action
