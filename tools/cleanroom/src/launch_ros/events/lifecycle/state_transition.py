"""StateTransition: a lifecycle node reported a transition on `<node>/transition_event`."""
from __future__ import annotations

from typing import Any

from launch import Event


class StateTransition(Event):
    """Event carrying one lifecycle_msgs/msg/TransitionEvent of a LifecycleNode action.

    `start_state`, `goal_state` and `transition` are the labels
    ('unconfigured', 'configuring', 'inactive', 'active', 'configure', ...)
    that OnStateTransition matches on.
    """

    name = 'launch_ros.events.lifecycle.StateTransition'

    def __init__(self, *, action: Any, msg: Any) -> None:
        super().__init__()
        self.__action = action
        self.__msg = msg

    @property
    def action(self) -> Any:
        return self.__action

    @property
    def msg(self) -> Any:
        return self.__msg

    @property
    def timestamp(self) -> int:
        return self.__msg.timestamp

    @property
    def transition(self) -> str:
        return self.__msg.transition.label

    @property
    def start_state(self) -> str:
        return self.__msg.start_state.label

    @property
    def goal_state(self) -> str:
        return self.__msg.goal_state.label

    def __repr__(self) -> str:
        return (f'StateTransition(node={getattr(self.__action, "node_name", None)!r}, '
                f'{self.start_state!r} -> {self.goal_state!r})')
