"""Converting parameter values between rcl_interfaces messages, Python and text.

Kept apart from the verbs so the conversions (YAML in, `ros2 param get`
wording and `ros2 param dump` nesting out) can be tested without ROS running.
"""
from __future__ import annotations

from typing import Any

import yaml
from rcl_interfaces.msg import ParameterType, ParameterValue
from rclpy.parameter import parameter_value_to_python

# ParameterType constant -> (ParameterValue field, word used by `ros2 param get`)
_FIELDS = {
    ParameterType.PARAMETER_BOOL: ('bool_value', 'Boolean value is'),
    ParameterType.PARAMETER_INTEGER: ('integer_value', 'Integer value is'),
    ParameterType.PARAMETER_DOUBLE: ('double_value', 'Double value is'),
    ParameterType.PARAMETER_STRING: ('string_value', 'String value is'),
    ParameterType.PARAMETER_BYTE_ARRAY: ('byte_array_value', 'Byte values are'),
    ParameterType.PARAMETER_BOOL_ARRAY: ('bool_array_value', 'Boolean values are'),
    ParameterType.PARAMETER_INTEGER_ARRAY: ('integer_array_value', 'Integer values are'),
    ParameterType.PARAMETER_DOUBLE_ARRAY: ('double_array_value', 'Double values are'),
    ParameterType.PARAMETER_STRING_ARRAY: ('string_array_value', 'String values are'),
}

# ParameterType constant -> the word `ros2 param list --param-type` prints.
_TYPE_NAMES = {
    ParameterType.PARAMETER_BOOL: 'boolean',
    ParameterType.PARAMETER_INTEGER: 'integer',
    ParameterType.PARAMETER_DOUBLE: 'double',
    ParameterType.PARAMETER_STRING: 'string',
    ParameterType.PARAMETER_BYTE_ARRAY: 'byte array',
    ParameterType.PARAMETER_BOOL_ARRAY: 'boolean array',
    ParameterType.PARAMETER_INTEGER_ARRAY: 'integer array',
    ParameterType.PARAMETER_DOUBLE_ARRAY: 'double array',
    ParameterType.PARAMETER_STRING_ARRAY: 'string array',
}


def type_name(value: ParameterValue) -> str:
    """`double array` etc.: the type a parameter value has, in `--param-type` words."""
    return _TYPE_NAMES.get(value.type, 'not set')


def to_python(value: ParameterValue) -> Any:
    """The plain Python value (arrays as lists); None when the parameter is not set.

    rclpy's conversion, but a byte array as its numbers: rclpy gives one-byte
    `bytes`, which `ros2 param get` would print as b'..' and the dump as !!binary.
    A type outside ParameterType counts as not set instead of raising.
    """
    if value.type not in _FIELDS:
        return None
    python = parameter_value_to_python(value)
    if value.type == ParameterType.PARAMETER_BYTE_ARRAY:
        return [item if isinstance(item, int) else ord(item) for item in python]
    return python


def describe(value: ParameterValue, hide_type: bool = False) -> str | None:
    """The line `ros2 param get` prints, e.g. `Integer value is: 3`; None if not set."""
    if value.type not in _FIELDS:
        return None
    python = to_python(value)
    return str(python) if hide_type else f'{_FIELDS[value.type][1]}: {python}'


def from_text(text: str) -> ParameterValue:
    """Parse a command-line value as YAML, the way `ros2 param set` does.

    `7` is an integer, `7.0` a double, `true` a boolean, `[1, 2]` an integer
    array; anything YAML cannot type (or a mixed list) stays the literal string.
    """
    try:
        parsed = yaml.safe_load(text)
    except yaml.YAMLError:
        parsed = text
    return from_python(parsed, fallback=text)


def from_python(value: Any, fallback: str | None = None) -> ParameterValue:
    """A ParameterValue for a Python scalar or homogeneous list."""
    result = ParameterValue()
    scalar_types = ((bool, ParameterType.PARAMETER_BOOL), (int, ParameterType.PARAMETER_INTEGER),
                    (float, ParameterType.PARAMETER_DOUBLE), (str, ParameterType.PARAMETER_STRING))
    for python_type, parameter_type in scalar_types:
        if type(value) is python_type:
            result.type = parameter_type
            setattr(result, _FIELDS[parameter_type][0], value)
            return result
    if isinstance(value, list) and value:
        array_types = ((bool, ParameterType.PARAMETER_BOOL_ARRAY),
                       (int, ParameterType.PARAMETER_INTEGER_ARRAY),
                       (float, ParameterType.PARAMETER_DOUBLE_ARRAY),
                       (str, ParameterType.PARAMETER_STRING_ARRAY))
        for python_type, parameter_type in array_types:
            if all(type(item) is python_type for item in value):
                result.type = parameter_type
                setattr(result, _FIELDS[parameter_type][0], value)
                return result
    result.type = ParameterType.PARAMETER_STRING
    result.string_value = fallback if fallback is not None else str(value)
    return result


def nest(flat: dict[str, Any]) -> dict[str, Any]:
    """`{'a.b': 1}` -> `{'a': {'b': 1}}`: dotted names as the YAML tree of a params file."""
    tree: dict[str, Any] = {}
    for name, value in flat.items():
        *parents, leaf = name.split('.')
        branch = tree
        for part in parents:
            branch = branch.setdefault(part, {})
        branch[leaf] = value
    return tree


def dump_yaml(node_name: str, values: dict[str, Any]) -> str:
    """The parameters file `ros2 param dump` prints for one node."""
    document = {node_name: {'ros__parameters': nest(values)}}
    return yaml.safe_dump(document, default_flow_style=False, allow_unicode=True,
                          width=float('inf'))
