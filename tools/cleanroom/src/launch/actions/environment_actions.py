"""Change the environment processes get, in the current scope."""
from __future__ import annotations

import os
from collections.abc import MutableMapping
from typing import TYPE_CHECKING

from ..action import Action
from ..conditions.evaluate_condition_expression import evaluate_condition_expression
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from ._scoped_store_actions import SetInStore, UnsetInStore

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


def _subs(value: object) -> list[Substitution]:
    return normalize_to_list_of_substitutions(value)


class SetEnvironmentVariable(SetInStore):
    """Set variable `name` to `value` for processes started later in this scope."""

    def _store(self, context: LaunchContext) -> MutableMapping[str, str]:
        return context.environment


class UnsetEnvironmentVariable(UnsetInStore):
    """Remove variable `name` for processes started later in this scope."""

    def _store(self, context: LaunchContext) -> MutableMapping[str, str]:
        return context.environment


class AppendEnvironmentVariable(Action):
    """Append (or prepend) `value` to a path-like variable, with `separator` between."""

    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType, *,
                 prepend: object = False, separator: SomeSubstitutionsType = os.pathsep,
                 **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__name = _subs(name)
        self.__value = _subs(value)
        self.__prepend = prepend if isinstance(prepend, bool) else _subs(prepend)
        self.__separator = _subs(separator)

    @property
    def name(self) -> list[Substitution]:
        """The variable name, as substitutions."""
        return self.__name

    @property
    def value(self) -> list[Substitution]:
        """The value, as substitutions."""
        return self.__value

    def execute(self, context: LaunchContext) -> None:
        """Append or prepend."""
        name = perform_substitutions(context, self.__name)
        value = perform_substitutions(context, self.__value)
        separator = perform_substitutions(context, self.__separator)
        prepend = self.__prepend if isinstance(self.__prepend, bool) \
            else evaluate_condition_expression(context, self.__prepend)
        current = context.environment.get(name)
        if current:
            value = value + separator + current if prepend else current + separator + value
        context.environment[name] = value


# Shown in reprs (`ros2 launch -p` prints them) under the module names Jazzy uses.
SetEnvironmentVariable.__module__ = 'launch.actions.set_environment_variable'
UnsetEnvironmentVariable.__module__ = 'launch.actions.unset_environment_variable'
AppendEnvironmentVariable.__module__ = 'launch.actions.append_environment_variable'
