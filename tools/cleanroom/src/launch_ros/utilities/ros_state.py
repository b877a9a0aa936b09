"""The ROS state that group scoping applies to, kept in launch configurations.

ARCHITECTURE.md fixes the keys: `ros_namespace` (str), `global_params`
(list of `(name, value)` or file paths) and `ros_remaps` (list of
`(src, dst)`).  Lists are replaced, never mutated, so a scoped group that
copied the dictionary cannot leak its additions to the parent.
"""
from __future__ import annotations

from typing import Any

from launch import LaunchContext

NAMESPACE_KEY = 'ros_namespace'
GLOBAL_PARAMS_KEY = 'global_params'
REMAPS_KEY = 'ros_remaps'


def pushed_namespace(context: LaunchContext) -> str | None:
    return context.launch_configurations.get(NAMESPACE_KEY) or None


def set_pushed_namespace(context: LaunchContext, namespace: str) -> None:
    context.launch_configurations[NAMESPACE_KEY] = namespace


def global_params(context: LaunchContext) -> list[Any]:
    return list(context.launch_configurations.get(GLOBAL_PARAMS_KEY) or [])


def add_global_param(context: LaunchContext, item: Any) -> None:
    """Append in place, as Jazzy does: a list that exists outside a scoped group is
    shared with it, so a SetParameter inside the group leaks out (frontends golden
    32_xml_groups); a list first created inside the group does not (golden 17)."""
    params = context.launch_configurations.get(GLOBAL_PARAMS_KEY)
    if params is None:
        context.launch_configurations[GLOBAL_PARAMS_KEY] = [item]
    else:
        params.append(item)


def global_remaps(context: LaunchContext) -> list[tuple[str, str]]:
    return list(context.launch_configurations.get(REMAPS_KEY) or [])


def add_global_remap(context: LaunchContext, rule: tuple[str, str]) -> None:
    context.launch_configurations[REMAPS_KEY] = global_remaps(context) + [rule]
