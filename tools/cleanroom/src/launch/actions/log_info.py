"""Print a message to the launch log as `[INFO] [launch.user]: ...`."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..action import Action
from ..logging import get_logger
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class LogInfo(Action):
    """Log `msg` (text and substitutions) at INFO on the 'launch.user' logger."""

    def __init__(self, *, msg: SomeSubstitutionsType, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self.__msg = normalize_to_list_of_substitutions(msg)

    @property
    def msg(self) -> list[Substitution]:
        """The message, as substitutions."""
        return self.__msg

    def describe(self) -> str:
        """Return a description."""
        return f"LogInfo({' + '.join(s.describe() for s in self.__msg)})"

    def execute(self, context: LaunchContext) -> None:
        """Log the message."""
        get_logger('launch.user').info(perform_substitutions(context, self.__msg))
