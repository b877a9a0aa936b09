"""Pick one of two values depending on a condition expression."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..conditions.evaluate_condition_expression import evaluate_condition_expression
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class IfElseSubstitution(Substitution):
    """`if_value` when `condition` is true ('true'/'1'), else `else_value`."""

    def __init__(self, condition: SomeSubstitutionsType,
                 if_value: SomeSubstitutionsType = '',
                 else_value: SomeSubstitutionsType = '') -> None:
        super().__init__()
        if if_value == else_value == '':
            raise RuntimeError('One of if_value and else_value must be specified')
        self.__condition = normalize_to_list_of_substitutions(condition)
        self.__if_value = normalize_to_list_of_substitutions(if_value)
        self.__else_value = normalize_to_list_of_substitutions(else_value)

    @property
    def condition(self) -> list[Substitution]:
        """The condition, as substitutions."""
        return self.__condition

    @property
    def if_value(self) -> list[Substitution]:
        """Value when true."""
        return self.__if_value

    @property
    def else_value(self) -> list[Substitution]:
        """Value when false."""
        return self.__else_value

    def describe(self) -> str:
        """Return the three list reprs, as Jazzy's `ros2 launch -p` shows them."""
        return (f'IfElseSubstitution({self.__condition!r}, {self.__if_value!r}, '
                f'{self.__else_value!r})')

    def perform(self, context: LaunchContext) -> str:
        """Return the chosen value."""
        chosen = self.__if_value if evaluate_condition_expression(context, self.__condition) \
            else self.__else_value
        return perform_substitutions(context, chosen)
