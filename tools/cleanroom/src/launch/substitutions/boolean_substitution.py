"""Boolean logic on 'true'/'false' style values: Not, And, Or, Any, All."""
from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..conditions.evaluate_condition_expression import evaluate_condition_expression
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


def _truth(context: LaunchContext, subs: list[Substitution]) -> bool:
    return evaluate_condition_expression(context, subs)


def _text(value: bool) -> str:
    return 'true' if value else 'false'


class NotSubstitution(Substitution):
    """'true' if the value is false, and the reverse."""

    def __init__(self, value: SomeSubstitutionsType) -> None:
        super().__init__()
        self.__value = normalize_to_list_of_substitutions(value)

    @property
    def value(self) -> list[Substitution]:
        """The operand, as substitutions."""
        return self.__value

    def describe(self) -> str:
        """Return the operand's list repr, as Jazzy's `ros2 launch -p` shows it."""
        return f'NotSubstitution({self.__value!r})'

    def perform(self, context: LaunchContext) -> str:
        """Return 'true' or 'false'."""
        return _text(not _truth(context, self.__value))


class _BinarySubstitution(Substitution):
    def __init__(self, left: SomeSubstitutionsType, right: SomeSubstitutionsType) -> None:
        super().__init__()
        self.__left = normalize_to_list_of_substitutions(left)
        self.__right = normalize_to_list_of_substitutions(right)

    @property
    def left(self) -> list[Substitution]:
        """The left operand, as substitutions."""
        return self.__left

    @property
    def right(self) -> list[Substitution]:
        """The right operand, as substitutions."""
        return self.__right

    def describe(self) -> str:
        """Return the operands' list reprs; Jazzy names Or 'AndSubstitution' too (observed)."""
        return f'AndSubstitution({self.__left!r} {self.__right!r})'


class AndSubstitution(_BinarySubstitution):
    """'true' if both operands are true."""

    def perform(self, context: LaunchContext) -> str:
        """Return 'true' or 'false'."""
        return _text(_truth(context, self.left) and _truth(context, self.right))


class OrSubstitution(_BinarySubstitution):
    """'true' if either operand is true."""

    def perform(self, context: LaunchContext) -> str:
        """Return 'true' or 'false'."""
        return _text(_truth(context, self.left) or _truth(context, self.right))


class _ManySubstitution(Substitution):
    def __init__(self, *args: SomeSubstitutionsType) -> None:
        super().__init__()
        self.__args = [normalize_to_list_of_substitutions(a) for a in args]

    @property
    def args(self) -> list[list[Substitution]]:
        """The operands, each as substitutions."""
        return self.__args

    def _values(self, context: LaunchContext) -> Iterable[bool]:
        return (_truth(context, a) for a in self.__args)

    def describe(self) -> str:
        """Return the operands' list reprs, space separated, as Jazzy's `ros2 launch -p`."""
        return f"{type(self).__name__}({' '.join(repr(a) for a in self.__args)})"


class AnySubstitution(_ManySubstitution):
    """'true' if any operand is true."""

    def perform(self, context: LaunchContext) -> str:
        """Return 'true' or 'false'."""
        return _text(any(self._values(context)))


class AllSubstitution(_ManySubstitution):
    """'true' if all operands are true."""

    def perform(self, context: LaunchContext) -> str:
        """Return 'true' or 'false'."""
        return _text(all(self._values(context)))
