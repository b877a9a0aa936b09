"""'true' if two values differ."""
from __future__ import annotations

from typing import TYPE_CHECKING

from .equals_substitution import EqualsSubstitution

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class NotEqualsSubstitution(EqualsSubstitution):
    """The negation of EqualsSubstitution."""

    def perform(self, context: LaunchContext) -> str:
        """Return 'true' or 'false'."""
        return 'false' if self._equal(context) else 'true'
