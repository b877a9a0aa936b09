"""Emitted when a process has been started."""
from .running_process_event import RunningProcessEvent


class ProcessStarted(RunningProcessEvent):
    """A process was started (again, when respawned)."""

    name = 'launch.events.process.ProcessStarted'
