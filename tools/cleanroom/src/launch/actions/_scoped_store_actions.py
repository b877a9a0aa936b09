"""Set and unset one entry of a scoped store of the launch context.

The environment and the launch configurations are both dicts that group
scoping pushes and pops; their Set/Unset actions differ only in the store.
"""
from __future__ import annotations

from collections.abc import MutableMapping
from typing import TYPE_CHECKING

from ..action import Action
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class _StoreAction(Action):
    def _store(self, context: LaunchContext) -> MutableMapping[str, str]:
        """The dict of the context this action changes."""
        raise NotImplementedError


class SetInStore(_StoreAction):
    """Set entry `name` to `value` (both may be substitutions)."""

    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType,
                 **kwargs: object) -> None:
        super().__init__(**kwargs)
        self._name = normalize_to_list_of_substitutions(name)
        self._value = normalize_to_list_of_substitutions(value)

    @property
    def name(self) -> list[Substitution]:
        """The name, as substitutions."""
        return self._name

    @property
    def value(self) -> list[Substitution]:
        """The value, as substitutions."""
        return self._value

    def execute(self, context: LaunchContext) -> None:
        """Set it."""
        self._store(context)[perform_substitutions(context, self._name)] = \
            perform_substitutions(context, self._value)


class UnsetInStore(_StoreAction):
    """Remove entry `name` (if set)."""

    def __init__(self, name: SomeSubstitutionsType, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self._name = normalize_to_list_of_substitutions(name)

    @property
    def name(self) -> list[Substitution]:
        """The name, as substitutions."""
        return self._name

    def execute(self, context: LaunchContext) -> None:
        """Unset it."""
        self._store(context).pop(perform_substitutions(context, self._name), None)
