"""Handle ProcessExited events."""
from collections.abc import Callable

from ..action import Action
from ..events.process import ProcessExited
from .on_action_event_base import OnActionEventBase


class OnProcessExit(OnActionEventBase):
    """React when `target_action`'s process (or any, if None) has exited."""

    _described_action_cls = 'ExecuteLocal'

    def __init__(self, *, target_action: Action | Callable | None = None,
                 on_exit: object, **kwargs: object) -> None:
        # late: actions import event_handlers (ExecuteProcess on_exit), so not at module level
        from ..actions.execute_process import ExecuteProcess

        super().__init__(action_matcher=target_action, on_event=on_exit,
                         target_event_cls=ProcessExited, target_action_cls=ExecuteProcess,
                         **kwargs)
