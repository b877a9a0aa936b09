"""Predicates selecting one action, for events that target actions."""
from collections.abc import Callable


def matches_action(target_action: object) -> Callable[[object], bool]:
    """Return a predicate true for `target_action` itself.

    Used as `process_matcher` of ShutdownProcess/SignalProcess
    and as `lifecycle_node_matcher` of launch_ros' ChangeState.
    """
    return lambda action: action is target_action
