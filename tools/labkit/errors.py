"""Errors labkit raises; their messages are written for a student to read."""
from __future__ import annotations


class LabkitError(RuntimeError):
    """Base class of the errors labkit raises for a lesson to show."""


class NodesNotFoundError(LabkitError):
    """`wait_for_nodes` ran out of time: the message names the missing nodes."""


class ProcessExitedError(LabkitError):
    """The background command ended while we were waiting for it."""
