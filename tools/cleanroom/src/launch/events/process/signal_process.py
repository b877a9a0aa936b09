"""Send a signal to some processes."""
import signal as signal_module
from collections.abc import Callable

from .process_targeted_event import ProcessTargetedEvent


class SignalProcess(ProcessTargetedEvent):
    """Send `signal_number` (a number, a signal.Signals or its name) to matching processes."""

    name = 'launch.events.process.SignalProcess'

    def __init__(self, *, signal_number: int | str | signal_module.Signals,
                 process_matcher: Callable[[object], bool]) -> None:
        super().__init__(process_matcher=process_matcher)
        if isinstance(signal_number, str):
            signal_number = getattr(signal_module, signal_number)
        self.__signal = signal_module.Signals(signal_number)

    @property
    def signal(self) -> signal_module.Signals:
        """The signal."""
        return self.__signal

    @property
    def signal_name(self) -> str:
        """E.g. 'SIGINT'."""
        return self.__signal.name
