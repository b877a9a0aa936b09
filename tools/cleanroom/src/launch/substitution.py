"""Base class of substitutions: values computed from the launch context at run time."""
from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .launch_context import LaunchContext


class Substitution:
    """A piece of text that is only known once the launch runs.

    Subclasses keep Python's default repr on purpose: error messages quote it
    (e.g. "expanded from '<...LaunchConfiguration object at 0x...>'") as Jazzy does.
    """

    def describe(self) -> str:
        """Return a human readable description, e.g. for `ros2 launch --show-args`."""
        return self.__repr__()

    def perform(self, context: LaunchContext) -> str:
        """Compute the text in `context`."""
        raise NotImplementedError(f'perform() not implemented for {type(self).__name__}')
