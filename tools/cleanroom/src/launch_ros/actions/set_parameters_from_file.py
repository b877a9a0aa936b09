"""SetParametersFromFile: a parameter file every node in scope gets first (golden 17)."""
from __future__ import annotations

from typing import Any

from launch import Action, LaunchContext

from ..parameter_descriptions import ParameterFile
from ..utilities.launch_cleanup import ensure_cleanup_registered
from ..utilities.ros_state import add_global_param


class SetParametersFromFile(Action):
    """Pass `--params-file FILE` to all nodes started after it in the same scope.

    The file goes before each node's own parameters, so node parameters win.
    """

    def __init__(self, filename: Any, *, allow_substs: Any = False, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__param_file = ParameterFile(filename, allow_substs=allow_substs)

    @property
    def param_file(self) -> ParameterFile:
        return self.__param_file

    def execute(self, context: LaunchContext) -> list[Any] | None:
        ensure_cleanup_registered(context)
        add_global_param(context, str(self.__param_file.evaluate(context)))
        return None
