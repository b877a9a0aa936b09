"""SetRemap: a remapping rule every node in scope gets (golden 07)."""
from __future__ import annotations

from typing import Any

from launch import Action, LaunchContext
from launch.utilities import normalize_to_list_of_substitutions

from ..utilities.ros_state import add_global_remap
from ..utilities.substitution_values import perform_text


class SetRemap(Action):
    """Remap `src` to `dst` for all nodes started after it in the same scope.

    Global rules come before a node's own rules on its command line.
    """

    def __init__(self, src: Any, dst: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__src = normalize_to_list_of_substitutions(src)
        self.__dst = normalize_to_list_of_substitutions(dst)

    @property
    def src(self) -> list[Any]:
        return self.__src

    @property
    def dst(self) -> list[Any]:
        return self.__dst

    def execute(self, context: LaunchContext) -> list[Any] | None:
        add_global_remap(context, (perform_text(context, self.__src),
                                   perform_text(context, self.__dst)))
        return None
