"""SetUseSimTime: `use_sim_time` for every node in scope, as a bool.

An Action of its own, not a SetParameter, as in Jazzy (observed: its MRO).
"""
from __future__ import annotations

from typing import Any

from launch import Action, LaunchContext

from ..parameter_descriptions import ParameterValue
from ..utilities.ros_state import add_global_param


class SetUseSimTime(Action):
    """Make every node in scope use (or not use) simulated time; the value must be a bool."""

    def __init__(self, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__given = value
        self.__value = ParameterValue(value, value_type=bool)

    @property
    def value(self) -> Any:
        return self.__given

    def execute(self, context: LaunchContext) -> list[Any] | None:
        add_global_param(context, ('use_sim_time', self.__value.evaluate(context)))
        return None
