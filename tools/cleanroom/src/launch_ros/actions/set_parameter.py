"""SetParameter: a parameter every node in scope gets as `-p name:=value` (golden 07)."""
from __future__ import annotations

from typing import Any

from launch import Action, LaunchContext

from ..parameter_descriptions import Parameter
from ..utilities.ros_state import add_global_param


class SetParameter(Action):
    """Set a parameter for all nodes started after it in the same scope."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__param = Parameter(name, value)

    @property
    def name(self) -> Any:
        return self.__param.name

    @property
    def value(self) -> Any:
        return self.__param.value

    def execute(self, context: LaunchContext) -> list[Any] | None:
        add_global_param(context, self.__param.evaluate(context))
        return None
