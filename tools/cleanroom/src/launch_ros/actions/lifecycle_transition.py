"""LifecycleTransition: walk lifecycle nodes through a sequence of transitions."""
from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import lifecycle_msgs.msg
from launch import Action, LaunchContext
from launch.actions import EmitEvent, RegisterEventHandler
from launch.utilities import normalize_to_list_of_substitutions

from ..event_handlers import OnStateTransition
from ..events.lifecycle import ChangeState, StateTransition
from ..utilities.substitution_values import perform_text

_T = lifecycle_msgs.msg.Transition


class LifecycleTransition(Action):
    """Request `transition_ids` in order from every node in `lifecycle_node_names`.

    The next transition is requested once the node reports reaching the goal
    state of the previous one, so a failed transition stops the chain.
    """

    transition_targets = {
        _T.TRANSITION_CONFIGURE: {'start_state': 'configuring', 'goal_state': 'inactive'},
        _T.TRANSITION_CLEANUP: {'start_state': 'cleaningup', 'goal_state': 'unconfigured'},
        _T.TRANSITION_ACTIVATE: {'start_state': 'activating', 'goal_state': 'active'},
        _T.TRANSITION_DEACTIVATE: {'start_state': 'deactivating', 'goal_state': 'inactive'},
        _T.TRANSITION_UNCONFIGURED_SHUTDOWN: {'start_state': 'shuttingdown',
                                              'goal_state': 'finalized'},
        _T.TRANSITION_INACTIVE_SHUTDOWN: {'start_state': 'shuttingdown',
                                          'goal_state': 'finalized'},
        _T.TRANSITION_ACTIVE_SHUTDOWN: {'start_state': 'shuttingdown',
                                        'goal_state': 'finalized'},
    }

    def __init__(self, *, lifecycle_node_names: Iterable[Any], transition_ids: Iterable[Any],
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__names = [normalize_to_list_of_substitutions(n) for n in lifecycle_node_names]
        self.__transitions = [self._transition_id(t) for t in transition_ids]

    @classmethod
    def _transition_id(cls, transition: Any) -> int:
        if isinstance(transition, str) and not transition.isdigit():
            attr = transition.upper()
            attr = attr if attr.startswith('TRANSITION_') else 'TRANSITION_' + attr
            transition = getattr(_T, attr, transition)
        transition = int(transition)
        if transition not in cls.transition_targets:
            raise ValueError(f'transition {transition} is not one LifecycleTransition can '
                             f'wait for; expected one of {sorted(cls.transition_targets)}')
        return transition

    def execute(self, context: LaunchContext) -> list[Any] | None:
        entities: list[Any] = []
        for name_subs in self.__names:
            name = perform_text(context, name_subs)
            if not name.startswith('/'):
                name = '/' + name
            entities += self._chain(name)
        return entities

    def _chain(self, node_name: str) -> list[Any]:
        def matcher_for(node: str) -> Any:
            return lambda action: getattr(action, 'node_name', None) == node

        entities: list[Any] = []
        steps = zip(self.__transitions[:-1], self.__transitions[1:], strict=True)
        for previous, following in steps:
            target = self.transition_targets[previous]

            def reached(event: Any, target: dict = target) -> bool:
                return (isinstance(event, StateTransition)
                        and getattr(event.action, 'node_name', None) == node_name
                        and event.goal_state == target['goal_state']
                        and event.start_state == target['start_state'])

            entities.append(RegisterEventHandler(OnStateTransition(
                matcher=reached, handle_once=True,
                entities=[EmitEvent(event=ChangeState(
                    lifecycle_node_matcher=matcher_for(node_name),
                    transition_id=following))])))
        if self.__transitions:
            entities.append(EmitEvent(event=ChangeState(
                lifecycle_node_matcher=matcher_for(node_name),
                transition_id=self.__transitions[0])))
        return entities
