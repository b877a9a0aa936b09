"""Predicates selecting the events of one action."""
from typing import Callable

from ..event import Event


def matches_action(target_action: object) -> Callable[[Event], bool]:
    """Return a predicate true for events whose `action` is `target_action`."""
    return lambda event: getattr(event, 'action', None) is target_action
