"""Parameter values against a ParameterSpec: ROS type names, exact values, ranges.

Used by both checks, so that a value from a launch file and one read from a
running node are judged the same way.
"""
from __future__ import annotations

import math
from array import array
from typing import Any

from speccheck.spec import ParameterSpec

_SCALARS = ((bool, 'bool'), (int, 'integer'), (float, 'double'), (str, 'string'))
#: Array parameter values: lists, and array.array as rclpy may give numeric arrays.
_SEQUENCES = (list, tuple, array)


def ros_type(value: Any) -> str | None:
    """The ROS parameter type a Python value becomes (None for unset / unknown)."""
    if isinstance(value, (bytes, bytearray)):
        return 'byte_array'
    if isinstance(value, _SEQUENCES):
        kinds = {ros_type(item) for item in value}
        if len(kinds) == 1 and None not in kinds and '_array' not in next(iter(kinds)):
            return f'{kinds.pop()}_array'
        return 'array' if not value else None
    for python_type, name in _SCALARS:  # bool first: True is also an int
        if isinstance(value, python_type):
            return name
    return None


def show(value: Any) -> str:
    """`value` as Python writes the spec's YAML value: an array as a list, whether it
    came as a list, a tuple (Jazzy's launch_ros evaluates parameters to tuples) or
    an array.array (rclpy), so that the same value reads the same everywhere."""
    return repr(_plain(value))


def _plain(value: Any) -> Any:
    if isinstance(value, _SEQUENCES):
        return [_plain(item) for item in value]
    return value


def judge(spec: ParameterSpec, value: Any) -> str | None:
    """None when `value` meets `spec`, else why not (type first, then value or range)."""
    actual = ros_type(value)
    type_ok = actual == spec.type or (actual == 'array' and spec.type.endswith('_array'))
    if not type_ok:
        return f'type {actual or "unknown"} ({show(value)}), the spec says {spec.type}'
    if spec.has_value and not _equal(value, spec.value):
        return f'value {show(value)}, the spec says {show(spec.value)}'
    if spec.min is not None and not value >= spec.min:
        return f'value {show(value)} is below the minimum {spec.min:g}'
    if spec.max is not None and not value <= spec.max:
        return f'value {show(value)} is above the maximum {spec.max:g}'
    return None


def expectation(spec: ParameterSpec) -> str:
    """What the spec asks for, in words: 'double 2.0', 'integer in [1, 10]'."""
    if spec.has_value:
        return f'{spec.type} {show(spec.value)}'
    if spec.min is not None or spec.max is not None:
        low = '-inf' if spec.min is None else f'{spec.min:g}'
        high = 'inf' if spec.max is None else f'{spec.max:g}'
        return f'{spec.type} in [{low}, {high}]'
    return spec.type


def _equal(actual: Any, wanted: Any) -> bool:
    if isinstance(actual, float) or isinstance(wanted, float):
        try:
            return math.isclose(float(actual), float(wanted), rel_tol=1e-9, abs_tol=1e-12)
        except (TypeError, ValueError):
            return False
    if isinstance(actual, _SEQUENCES) and isinstance(wanted, _SEQUENCES):
        return len(actual) == len(wanted) and all(map(_equal, actual, wanted))
    return actual == wanted
