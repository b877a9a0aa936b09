"""PushRosNamespace: prefix the namespace of every node that follows in scope."""
from __future__ import annotations

from typing import Any

from launch import Action, LaunchContext
from launch.utilities import normalize_to_list_of_substitutions

from ..utilities.namespace_utils import make_namespace_absolute, prefix_namespace
from ..utilities.ros_state import pushed_namespace, set_pushed_namespace
from ..utilities.substitution_values import perform_text


class PushROSNamespace(Action):
    """Push a namespace; it is popped with the enclosing scoped GroupAction.

    Relative pushes compose ('robot1' then 'arm' gives /robot1/arm), an
    absolute push replaces what was pushed before (golden 06).
    """

    def __init__(self, namespace: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__namespace = normalize_to_list_of_substitutions(namespace)

    @property
    def namespace(self) -> list[Any]:
        return self.__namespace

    def execute(self, context: LaunchContext) -> list[Any] | None:
        namespace = perform_text(context, self.__namespace)
        pushed = prefix_namespace(pushed_namespace(context), namespace)
        if pushed:
            set_pushed_namespace(context, make_namespace_absolute(pushed))
        return None


PushRosNamespace = PushROSNamespace  # Jazzy's class is PushROSNamespace (its repr says so)
