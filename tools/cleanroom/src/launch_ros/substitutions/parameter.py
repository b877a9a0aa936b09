"""Parameter substitution: the value of a parameter set with SetParameter in scope."""
from __future__ import annotations

from typing import Any

from launch import LaunchContext, Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from ..utilities.ros_state import global_params
from ._failure import SubstitutionFailure


class Parameter(Substitution):
    """Expand to the value SetParameter gave `name` (the latest one in scope)."""

    def __init__(self, name: Any) -> None:
        super().__init__()
        self.__name = normalize_to_list_of_substitutions(name)

    @property
    def name(self) -> list[Substitution]:
        return self.__name

    def describe(self) -> str:
        """Return e.g. Parameter(name='use_sim_time'), as Jazzy's `ros2 launch -p` shows it."""
        return f"Parameter(name={' + '.join(s.describe() for s in self.__name)})"

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.__name)
        for item in reversed(global_params(context)):
            if isinstance(item, tuple) and item[0] == name:
                return str(item[1])
        raise SubstitutionFailure(f"parameter '{name}' not found")
