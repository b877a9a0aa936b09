"""`-p name:=value` and `-e name:=value` of `ros2 component load|standalone`.

Jazzy types a value by YAML, a little differently from `ros2 param set`
(param_values.from_text): an empty list is a boolean array, `[1, true]` an
integer array, YAML null stays the literal text, and a mapping or a date is
put into `string_value` unconverted, so the request fails when it is sent
(a TypeError, as with Jazzy).
"""
from __future__ import annotations

from typing import Any

import yaml
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue

_SCALARS = ((bool, ParameterType.PARAMETER_BOOL, 'bool_value'),
            (int, ParameterType.PARAMETER_INTEGER, 'integer_value'),
            (float, ParameterType.PARAMETER_DOUBLE, 'double_value'),
            (str, ParameterType.PARAMETER_STRING, 'string_value'))
_ARRAYS = ((bool, ParameterType.PARAMETER_BOOL_ARRAY, 'bool_array_value'),
           (int, ParameterType.PARAMETER_INTEGER_ARRAY, 'integer_array_value'),
           (float, ParameterType.PARAMETER_DOUBLE_ARRAY, 'double_array_value'),
           (str, ParameterType.PARAMETER_STRING_ARRAY, 'string_array_value'))


def _value(parsed: Any, text: str) -> ParameterValue:
    value = ParameterValue(type=ParameterType.PARAMETER_STRING)
    if parsed is None:
        value.string_value = text
        return value
    kinds = _ARRAYS if isinstance(parsed, list) else _SCALARS
    for python_type, parameter_type, field in kinds:
        items = parsed if isinstance(parsed, list) else [parsed]
        if all(isinstance(item, python_type) for item in items):
            value.type = parameter_type
            setattr(value, field, parsed)
            return value
    # a mixed list keeps its text; anything else goes in as it is (and fails to send)
    value.string_value = text if isinstance(parsed, list) else parsed
    return value


def parameter_value(text: str) -> ParameterValue:
    """The value of `name:=VALUE`, typed by YAML; unparsable text stays a string."""
    try:
        parsed = yaml.safe_load(text)
    except yaml.YAMLError:
        parsed = text
    return _value(parsed, text)


def parameters(assignments: list[str] | None) -> list[Parameter]:
    """`['a:=1', 'b']` -> Parameters; a missing value is the empty string."""
    result = []
    for assignment in assignments or []:
        name, _, text = assignment.partition(':=')
        result.append(Parameter(name=name, value=parameter_value(text)))
    return result
