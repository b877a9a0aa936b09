"""The value of an environment variable in the launch's (scoped) environment."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class EnvironmentVariable(Substitution):
    """Look up a variable in `context.environment`, else `default_value`, else fail."""

    def __init__(self, name: SomeSubstitutionsType, *,
                 default_value: SomeSubstitutionsType | None = None) -> None:
        super().__init__()
        self.__name = normalize_to_list_of_substitutions(name)
        self.__default_value = None if default_value is None \
            else normalize_to_list_of_substitutions(default_value)

    @property
    def name(self) -> list[Substitution]:
        """The variable name, as substitutions."""
        return self.__name

    @property
    def default_value(self) -> list[Substitution] | None:
        """The default, as substitutions, or None."""
        return self.__default_value

    def describe(self) -> str:
        """Return e.g. EnvVar('HOME')."""
        return f"EnvVar({' + '.join(s.describe() for s in self.__name)})"

    def perform(self, context: LaunchContext) -> str:
        """Return the value; SubstitutionFailure if unset and there is no default."""
        name = perform_substitutions(context, self.__name)
        value = context.environment.get(name)
        if value is not None:
            return value
        if self.__default_value is None:
            raise SubstitutionFailure(f"environment variable '{name}' does not exist")
        return perform_substitutions(context, self.__default_value)
