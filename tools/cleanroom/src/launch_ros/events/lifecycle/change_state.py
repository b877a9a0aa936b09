"""ChangeState: ask the LifecycleNode actions picked by a matcher to make a transition."""
from __future__ import annotations

from collections.abc import Callable
from typing import Any

import lifecycle_msgs.msg
from launch import Event


def _constants(message_class: type, prefixes: tuple[str, ...],
               excluded: tuple[str, ...] = ()) -> dict[int, str]:
    return {getattr(message_class, attr): attr for attr in dir(message_class)
            if attr.startswith(prefixes) and not attr.startswith(excluded)
            and isinstance(getattr(message_class, attr), int)}


class ChangeState(Event):
    """Event emitted (with EmitEvent) to request a lifecycle transition.

    `transition_id` is one of lifecycle_msgs.msg.Transition.TRANSITION_*;
    `lifecycle_node_matcher(action)` says which LifecycleNode actions act
    on it (typically `launch.events.matches_action(node)`).
    """

    name = 'launch_ros.events.lifecycle.ChangeState'

    valid_transitions = _constants(lifecycle_msgs.msg.Transition, ('TRANSITION_',),
                                   ('TRANSITION_CALLBACK_', 'TRANSITION_ON_'))
    valid_states = _constants(lifecycle_msgs.msg.State, ('PRIMARY_STATE_', 'TRANSITION_STATE_'))

    def __init__(self, *, lifecycle_node_matcher: Callable[[Any], bool],
                 transition_id: int) -> None:
        super().__init__()
        if transition_id not in self.valid_transitions:
            raise ValueError(
                f"given transition_id of '{transition_id}', expected one of "
                f'{self.valid_transitions}')
        self.__lifecycle_node_matcher = lifecycle_node_matcher
        self.__transition_id = transition_id

    @property
    def lifecycle_node_matcher(self) -> Callable[[Any], bool]:
        return self.__lifecycle_node_matcher

    @property
    def transition_id(self) -> int:
        return self.__transition_id

    def __repr__(self) -> str:
        label = self.valid_transitions.get(self.__transition_id, self.__transition_id)
        return f'ChangeState(transition_id={label})'
