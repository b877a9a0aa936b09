"""A value from the context locals, e.g. 'event.returncode' inside an event handler."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..substitution import Substitution
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


class LocalSubstitution(Substitution):
    """str() of `context.locals.<expression>`."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        super().__init__()
        self.__expression = expression
        self.__description = description

    @property
    def expression(self) -> str:
        """The expression after `context.locals.`."""
        return self.__expression

    @property
    def description(self) -> str | None:
        """An optional description."""
        return self.__description

    def describe(self) -> str:
        """`LocalVar('<description or expression>')`, as `ros2 launch -p` shows it."""
        return f"LocalVar('{self.__description or self.__expression}')"

    def perform(self, context: LaunchContext) -> str:
        """Evaluate `context.locals.<expression>` and return its str()."""
        try:
            return str(eval('context.locals.' + self.__expression, {'context': context}))
        except Exception as exc:
            raise SubstitutionFailure(
                f"LocalSubstitution failed to evaluate 'context.locals.{self.__expression}': "
                f'{exc}') from exc
