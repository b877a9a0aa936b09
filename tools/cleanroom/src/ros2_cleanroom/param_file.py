"""Reading a ROS parameters file for `ros2 param load`, kept apart from ROS for testing.

The parameters of every node in the file apply to the target node: first
those under the `/**` wildcard (unless it is left out), then each node's in
file order, a later value of a name replacing an earlier one.  Nested keys
become dotted names.  A value is typed as `ros2 param set` types its text.
"""
from __future__ import annotations

from typing import Any

import yaml
from rcl_interfaces.msg import ParameterType, ParameterValue

from ros2_cleanroom import param_values

WILDCARD = '/**'


def read_parameter_file(path: str, use_wildcard: bool = True) -> dict[str, Any]:
    """Every parameter the file gives the node, as dotted name -> YAML value.

    Raises RuntimeError naming the node whose entry lacks `ros__parameters`;
    an unreadable file or malformed YAML raises what opening or parsing raises.
    """
    with open(path) as stream:
        document = yaml.safe_load(stream)
    merged: dict[str, Any] = {}
    if use_wildcard and WILDCARD in document:
        merged.update(document[WILDCARD]['ros__parameters'])
    for node_name in document.keys():
        if node_name == WILDCARD:
            continue
        if 'ros__parameters' not in document[node_name]:
            raise RuntimeError(
                f'YAML file is not a valid ROS parameter file for node {node_name}')
        merged.update(document[node_name]['ros__parameters'])
    return flatten(merged)


def flatten(tree: dict[str, Any], prefix: str = '') -> dict[str, Any]:
    """`{'a': {'b': 1}}` -> `{'a.b': 1}`, in the file's order."""
    flat: dict[str, Any] = {}
    for key, value in tree.items():
        name = f'{prefix}{key}'
        if isinstance(value, dict):
            flat.update(flatten(value, name + '.'))
        else:
            flat[name] = value
    return flat


def to_parameter_value(value: Any) -> ParameterValue:
    """The value a loaded entry sets: its text typed again as YAML (`None` stays the
    string 'None', a mixed list its text), an empty list an empty boolean array."""
    if isinstance(value, list) and not value:
        return ParameterValue(type=ParameterType.PARAMETER_BOOL_ARRAY, bool_array_value=[])
    return param_values.from_text(str(value))
