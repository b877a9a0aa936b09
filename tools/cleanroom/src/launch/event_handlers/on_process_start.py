"""Handle ProcessStarted events."""
from collections.abc import Callable

from ..action import Action
from ..events.process import ProcessStarted
from .on_action_event_base import OnActionEventBase


class OnProcessStart(OnActionEventBase):
    """React when `target_action`'s process (or any, if None) has started."""

    _described_action_cls = 'ExecuteProcess'

    def __init__(self, *, target_action: Action | Callable | None = None,
                 on_start: object, **kwargs: object) -> None:
        # late: actions import event_handlers (ExecuteProcess on_exit), so not at module level
        from ..actions.execute_process import ExecuteProcess

        super().__init__(action_matcher=target_action, on_event=on_start,
                         target_event_cls=ProcessStarted, target_action_cls=ExecuteProcess,
                         **kwargs)
