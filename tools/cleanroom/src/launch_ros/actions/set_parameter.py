"""SetParameter: a parameter every node in scope gets as `-p name:=value` (golden 07)."""
from __future__ import annotations

from typing import Any

from launch import Action, LaunchContext, Substitution
from launch.utilities import normalize_to_list_of_substitutions

from .._support.substitution_values import perform_text
from ..parameter_descriptions import ParameterValue
from ..utilities.ros_state import add_global_param


class SetParameter(Action):
    """Set a parameter for all nodes started after it in the same scope.

    `value` may be a ParameterValue (to give its type), unlike a Parameter's.
    """

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__name = tuple(normalize_to_list_of_substitutions(name))
        self.__given = (tuple(normalize_to_list_of_substitutions(value))
                        if isinstance(value, (str, Substitution)) else value)
        self.__value = value if isinstance(value, ParameterValue) else ParameterValue(value)

    @property
    def name(self) -> tuple[Substitution, ...]:
        return self.__name

    @property
    def value(self) -> Any:
        """What was given, as Jazzy keeps it (text as a tuple of substitutions)."""
        return self.__given

    def execute(self, context: LaunchContext) -> list[Any] | None:
        add_global_param(context, (perform_text(context, self.__name),
                                   self.__value.evaluate(context)))
        return None
