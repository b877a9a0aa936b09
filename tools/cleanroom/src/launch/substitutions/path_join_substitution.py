"""Join path components with the platform separator."""
from __future__ import annotations

import os
from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class PathJoinSubstitution(Substitution):
    """os.path.join of the performed substitutions, one path component each.

    As in Jazzy, `substitutions` is normalised like any SomeSubstitutionsType:
    each item is a str or a Substitution, and a list inside the list (to
    concatenate text within one component) is refused with the TypeError of
    normalize_to_list_of_substitutions.
    """

    def __init__(self, substitutions: SomeSubstitutionsType) -> None:
        super().__init__()
        self.__substitutions = normalize_to_list_of_substitutions(substitutions)

    @property
    def substitutions(self) -> list[Substitution]:
        """The path components, one substitution each."""
        return self.__substitutions

    def describe(self) -> str:
        """Return a description of the components, as Jazzy writes it."""
        return f"PathJoin('{' + '.join(s.describe() for s in self.__substitutions)}')"

    def perform(self, context: LaunchContext) -> str:
        """Return the joined path."""
        parts = [context.perform_substitution(s) for s in self.__substitutions]
        return os.path.join(*parts) if parts else ''
