"""The value of a launch configuration (launch argument)."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class LaunchConfiguration(Substitution):
    """Look up a launch configuration, falling back to `default` when given."""

    def __init__(self, variable_name: SomeSubstitutionsType, *,
                 default: object | None = None) -> None:
        super().__init__()
        self.__variable_name = normalize_to_list_of_substitutions(variable_name)
        if default is None:
            self.__default = None
        elif isinstance(default, (str, Substitution)) or hasattr(default, '__iter__'):
            self.__default = normalize_to_list_of_substitutions(default)
        else:  # numbers such as sigterm_timeout's default of 5
            self.__default = normalize_to_list_of_substitutions(str(default))

    @property
    def variable_name(self) -> list[Substitution]:
        """The name, as substitutions."""
        return self.__variable_name

    @property
    def default(self) -> list[Substitution] | None:
        """The default, as substitutions, or None."""
        return self.__default

    def describe(self) -> str:
        """Return e.g. LaunchConfig('robot_name')."""
        return f"LaunchConfig({' + '.join(s.describe() for s in self.__variable_name)})"

    def perform(self, context: LaunchContext) -> str:
        """Return the configuration's value; SubstitutionFailure if unset and no default."""
        name = perform_substitutions(context, self.__variable_name)
        if name in context.launch_configurations:
            return str(context.launch_configurations[name])
        if self.__default is None:
            raise SubstitutionFailure(f"launch configuration '{name}' does not exist")
        return perform_substitutions(context, self.__default)
