"""Ask some processes to stop (SIGINT, then SIGTERM, then SIGKILL)."""
from .process_targeted_event import ProcessTargetedEvent


class ShutdownProcess(ProcessTargetedEvent):
    """Stop the matching processes as the launch's shutdown would."""

    name = 'launch.events.process.ShutdownProcess'
