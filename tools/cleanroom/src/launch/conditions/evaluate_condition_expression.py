"""Turn the text of a condition into a bool, strictly."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext

VALID_TRUE_EXPRESSIONS = ['true', '1']
VALID_FALSE_EXPRESSIONS = ['false', '0']


class InvalidConditionExpressionError(Exception):
    """A condition expanded to something that is neither true nor false."""

    def __init__(self, expanded_expression: str, expression: list[Substitution],
                 valid_expressions: list[str]) -> None:
        super().__init__(
            f"invalid condition expression, expected one of [{', '.join(valid_expressions)}] "
            f"but got '{expanded_expression}', expanded from "
            f"'{''.join(str(sub) for sub in expression)}'")


def evaluate_condition_expression(context: LaunchContext, expression: list[Substitution]) -> bool:
    """Return True for 'true'/'1' and False for 'false'/'0' (any case, spaces ignored).

    Anything else raises InvalidConditionExpressionError: a typo like
    'Ture' must not silently count as false.
    """
    expanded = perform_substitutions(context, expression)
    lowered = expanded.strip().lower()
    if lowered in VALID_TRUE_EXPRESSIONS:
        return True
    if lowered in VALID_FALSE_EXPRESSIONS:
        return False
    raise InvalidConditionExpressionError(
        expanded, expression, VALID_TRUE_EXPRESSIONS + VALID_FALSE_EXPRESSIONS)
