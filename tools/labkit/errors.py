"""Errors labkit raises; their messages are written for a student to read."""
from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager


class LabkitError(RuntimeError):
    """Base class of the errors labkit raises for a lesson to show."""


class NodesNotFoundError(LabkitError):
    """`wait_for_nodes` ran out of time: the message names the missing nodes."""


class ProcessExitedError(LabkitError):
    """The background command ended while we were waiting for it."""


@contextmanager
def as_labkit_error() -> Iterator[None]:
    """speccheck's graph helpers (which labkit uses) raise RosError; lessons and
    graders catch LabkitError, so that is what labkit raises, with the same message.

    speccheck is imported here, not at the top: `import labkit` must get as far as
    saying that ROS 2 is not sourced, and speccheck's package needs rclpy."""
    from speccheck.ros_error import RosError

    try:
        yield
    except RosError as error:
        raise LabkitError(str(error)) from None
