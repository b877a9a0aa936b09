"""Handle ProcessIO events, per stream."""
from collections.abc import Callable

from ..action import Action
from ..event import Event
from ..events.process import ProcessIO
from .on_action_event_base import OnActionEventBase


class OnProcessIO(OnActionEventBase):
    """Call `on_stdout(event)` / `on_stderr(event)` / `on_stdin(event)` for process output.

    The callables get the ProcessIO event (its `text` is bytes) and may
    return entities.
    """

    _described_action_cls = 'ExecuteLocal'

    def __init__(self, *, target_action: Action | Callable | None = None,
                 on_stdin: Callable | None = None, on_stdout: Callable | None = None,
                 on_stderr: Callable | None = None, **kwargs: object) -> None:
        # late: actions import event_handlers (ExecuteProcess on_exit), so not at module level
        from ..actions.execute_process import ExecuteProcess

        self.__by_fd = {0: on_stdin, 1: on_stdout, 2: on_stderr}

        def handle(event: ProcessIO, context: object) -> object:  # `-p` names it, as Jazzy's
            return self.__by_fd[event.fd](event)
        super().__init__(action_matcher=target_action, on_event=handle,
                         target_event_cls=ProcessIO, target_action_cls=ExecuteProcess,
                         **kwargs)

    def _match(self, event: Event) -> bool:
        return super()._match(event) and self.__by_fd.get(event.fd) is not None
