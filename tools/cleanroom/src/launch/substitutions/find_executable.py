"""Full path of an executable found on the launch environment's PATH."""
from __future__ import annotations

import shutil
from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class FindExecutable(Substitution):
    """shutil.which(name) on PATH of `context.environment`; fails if not found."""

    def __init__(self, *, name: SomeSubstitutionsType) -> None:
        super().__init__()
        self.__name = normalize_to_list_of_substitutions(name)

    @property
    def name(self) -> list[Substitution]:
        """The executable name, as substitutions."""
        return self.__name

    def describe(self) -> str:
        """Return e.g. FindExec('python3')."""
        return f"FindExec({' + '.join(s.describe() for s in self.__name)})"

    def perform(self, context: LaunchContext) -> str:
        """Return the executable's path."""
        name = perform_substitutions(context, self.__name)
        found = shutil.which(name, path=context.environment.get('PATH'))
        if found is None:  # Jazzy names the substitution list, not the name it looked for
            raise SubstitutionFailure(f"executable '{self.__name}' not found on the PATH")
        return found
