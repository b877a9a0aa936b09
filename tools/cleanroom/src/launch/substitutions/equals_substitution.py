"""Compare two values: 'true' if equal, 'false' if not."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


def _normalize(value: Any) -> list[Substitution]:
    if value is None:
        return normalize_to_list_of_substitutions('')
    if isinstance(value, bool):
        return normalize_to_list_of_substitutions('true' if value else 'false')
    if isinstance(value, (int, float)):
        return normalize_to_list_of_substitutions(str(value))
    return normalize_to_list_of_substitutions(value)


def _as_bool(text: str) -> Any:
    lowered = text.strip().lower()
    return {'true': True, 'false': False}.get(lowered)


def _as_number(text: str) -> Any:
    try:
        return float(text)
    except ValueError:
        return None


def values_equal(left: str, right: str) -> bool:
    """Compare as booleans or numbers when both sides are, else as text.

    So that 'True' equals 'true' and '0.10' equals '0.1', as users mean.
    """
    left_bool, right_bool = _as_bool(left), _as_bool(right)
    if left_bool is not None and right_bool is not None:
        return left_bool == right_bool
    left_num, right_num = _as_number(left), _as_number(right)
    if left_num is not None and right_num is not None:
        return left_num == right_num
    return left == right


class EqualsSubstitution(Substitution):
    """'true' if both values are equal (see values_equal), else 'false'."""

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self.__left = _normalize(left)
        self.__right = _normalize(right)

    @property
    def left(self) -> list[Substitution]:
        """The left value, as substitutions."""
        return self.__left

    @property
    def right(self) -> list[Substitution]:
        """The right value, as substitutions."""
        return self.__right

    def describe(self) -> str:
        """Return the operands' list reprs, as Jazzy's `ros2 launch -p` shows them."""
        return f'{type(self).__name__}({self.__left!r} {self.__right!r})'

    def _equal(self, context: LaunchContext) -> bool:
        return values_equal(perform_substitutions(context, self.__left),
                            perform_substitutions(context, self.__right))

    def perform(self, context: LaunchContext) -> str:
        """Return 'true' or 'false'."""
        return 'true' if self._equal(context) else 'false'
