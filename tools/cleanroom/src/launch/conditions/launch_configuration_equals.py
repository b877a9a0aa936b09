"""Deprecated conditions comparing a launch configuration with a value."""
from __future__ import annotations

import warnings
from typing import TYPE_CHECKING

from ..condition import Condition
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


def _warn_deprecated(name: str, expected: object) -> None:
    # A Python warning, not a launch log line: that is how Jazzy reports it.
    warnings.warn(
        "The 'LaunchConfigurationEquals' and 'LaunchConfigurationNotEquals' Conditions are "
        "deprecated. Use the 'EqualsSubstitution' and 'NotEqualsSubstitution' substitutions "
        'instead! E.g.:\n'
        '  IfCondition(\n'
        f"  \tEqualsSubstitution(LaunchConfiguration('{name}'), {expected!r})\n"
        '  )',
        UserWarning, stacklevel=3)


class LaunchConfigurationEquals(Condition):
    """True when launch configuration `name` equals `expected_value` (as text).

    With `expected_value=None` it is true when the configuration is not set.
    """

    def __init__(self, launch_configuration_name: str,
                 expected_value: SomeSubstitutionsType | None) -> None:
        _warn_deprecated(launch_configuration_name, expected_value)
        self.__name = launch_configuration_name
        self.__expected = None if expected_value is None \
            else normalize_to_list_of_substitutions(expected_value)
        super().__init__(predicate=self._predicate_func)

    def _predicate_func(self, context: LaunchContext) -> bool:
        value = context.launch_configurations.get(self.__name)
        if self.__expected is None:
            return value is None
        return value is not None and str(value) == perform_substitutions(context, self.__expected)

    def describe(self) -> str:
        """Return a description."""
        return f'{type(self).__name__}({self.__name!r})'


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    """The negation of LaunchConfigurationEquals."""

    def _predicate_func(self, context: LaunchContext) -> bool:
        return not super()._predicate_func(context)
