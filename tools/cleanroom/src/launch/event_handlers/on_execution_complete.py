"""Handle ExecutionComplete events."""
from collections.abc import Callable

from ..action import Action
from ..events import ExecutionComplete
from .on_action_event_base import OnActionEventBase


class OnExecutionComplete(OnActionEventBase):
    """React when `target_action` (or any action, if None) has completed."""

    def __init__(self, *, target_action: Action | Callable | None = None,
                 on_completion: object, **kwargs: object) -> None:
        super().__init__(action_matcher=target_action, on_event=on_completion,
                         target_event_cls=ExecutionComplete, target_action_cls=Action,
                         **kwargs)
