"""Set or unset a launch configuration in the current scope."""
from __future__ import annotations

from typing import TYPE_CHECKING, List

from ..action import Action
from ..substitution import Substitution

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class SetLaunchConfiguration(Action):
    """Set launch configuration `name` to `value` (both may be substitutions)."""

    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType,
                 **kwargs: object) -> None:
        from ..utilities import normalize_to_list_of_substitutions

        super().__init__(**kwargs)
        self.__name = normalize_to_list_of_substitutions(name)
        self.__value = normalize_to_list_of_substitutions(value)

    @property
    def name(self) -> List[Substitution]:
        """The name, as substitutions."""
        return self.__name

    @property
    def value(self) -> List[Substitution]:
        """The value, as substitutions."""
        return self.__value

    def describe(self) -> str:
        """Return a description."""
        return (f"SetLaunchConfiguration({' + '.join(s.describe() for s in self.__name)}, "
                f"{' + '.join(s.describe() for s in self.__value)})")

    def execute(self, context: LaunchContext) -> None:
        """Set it."""
        from ..utilities import perform_substitutions

        context.launch_configurations[perform_substitutions(context, self.__name)] = \
            perform_substitutions(context, self.__value)


class UnsetLaunchConfiguration(Action):
    """Remove launch configuration `name` from the current scope (if set)."""

    def __init__(self, name: SomeSubstitutionsType, **kwargs: object) -> None:
        from ..utilities import normalize_to_list_of_substitutions

        super().__init__(**kwargs)
        self.__name = normalize_to_list_of_substitutions(name)

    @property
    def name(self) -> List[Substitution]:
        """The name, as substitutions."""
        return self.__name

    def execute(self, context: LaunchContext) -> None:
        """Unset it."""
        from ..utilities import perform_substitutions

        context.launch_configurations.pop(perform_substitutions(context, self.__name), None)
