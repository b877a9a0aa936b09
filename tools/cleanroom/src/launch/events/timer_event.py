"""The event a TimerAction emits when its period has passed."""
from ..event import Event


class TimerEvent(Event):
    """Emitted by TimerAction; its handler returns the timer's actions."""

    name = 'launch.events.TimerEvent'

    def __init__(self, *, timer_action: object) -> None:
        self.__timer_action = timer_action

    @property
    def timer_action(self) -> object:
        """The TimerAction whose period passed."""
        return self.__timer_action
