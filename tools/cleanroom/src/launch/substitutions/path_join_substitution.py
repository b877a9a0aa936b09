"""Join path components with the platform separator."""
from __future__ import annotations

import os
from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class PathJoinSubstitution(Substitution):
    """os.path.join of components, each of which may itself be substitutions."""

    def __init__(self, substitutions: Iterable[SomeSubstitutionsType]) -> None:
        super().__init__()
        self.__components = [normalize_to_list_of_substitutions(c) for c in substitutions]

    @property
    def substitutions(self) -> list[list[Substitution]]:
        """The components, each a list of substitutions."""
        return self.__components

    def describe(self) -> str:
        """Return a description of the components."""
        parts = ', '.join(' + '.join(s.describe() for s in c) for c in self.__components)
        return f'PathJoin([{parts}])'

    def perform(self, context: LaunchContext) -> str:
        """Return the joined path."""
        parts = [perform_substitutions(context, c) for c in self.__components]
        return os.path.join(*parts) if parts else ''
