"""Run an action only if an expression is true."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..condition import Condition
from ..utilities import normalize_to_list_of_substitutions
from .evaluate_condition_expression import evaluate_condition_expression

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class IfCondition(Condition):
    """True when the expression expands to 'true' or '1' (case-insensitive)."""

    def __init__(self, predicate_expression: SomeSubstitutionsType) -> None:
        self.__expression = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=self._predicate_func)

    def _predicate_func(self, context: LaunchContext) -> bool:
        return evaluate_condition_expression(context, self.__expression)

    def describe(self) -> str:
        """Return a description."""
        return f"IfCondition({' + '.join(s.describe() for s in self.__expression)})"
