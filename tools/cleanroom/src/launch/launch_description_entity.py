"""Base class of everything a LaunchDescription can hold."""
from __future__ import annotations

import asyncio
from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .launch_context import LaunchContext


class LaunchDescriptionEntity:
    """Something the LaunchService visits; visiting may yield further entities.

    The LaunchService visits entities depth first and synchronously, which is
    what makes push/pop style scoping (GroupAction) work.
    """

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Do this entity's work and return entities to visit next, if any."""
        raise NotImplementedError(f'visit() not implemented for {type(self).__name__}')

    def describe(self) -> str:
        """Return a one-line description (`ros2 launch --print` has its own format)."""
        return self.__repr__()

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """Entities that are always visited after this one (for introspection)."""
        return []

    def describe_conditional_sub_entities(
            self) -> list[tuple[str, Sequence[LaunchDescriptionEntity]]]:
        """(condition text, entities) pairs visited only when something happens."""
        return []

    def get_asyncio_future(self) -> asyncio.Future | None:
        """A future that completes when this entity's work is over, or None if it is."""
        return None
