"""Every parameter type through `ros2 param get`'s line and `ros2 param dump`'s YAML, offline.

The running-node tests cover the types the recorded `/param_dump` node has;
these cover the rest (byte, bool and integer arrays, unset), where rclpy's
conversion gives `bytes` items that must still print as numbers.
"""
from __future__ import annotations

import pytest
from rcl_interfaces.msg import ParameterType, ParameterValue
from ros2_cleanroom.param_values import describe, dump_yaml, to_python

CASES = [
    (ParameterValue(type=ParameterType.PARAMETER_BOOL, bool_value=True),
     True, 'Boolean value is: True'),
    (ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=3),
     3, 'Integer value is: 3'),
    (ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=2.0),
     2.0, 'Double value is: 2.0'),
    (ParameterValue(type=ParameterType.PARAMETER_STRING, string_value='laser'),
     'laser', 'String value is: laser'),
    (ParameterValue(type=ParameterType.PARAMETER_BYTE_ARRAY, byte_array_value=[b'\x01', b'\xff']),
     [1, 255], 'Byte values are: [1, 255]'),
    (ParameterValue(type=ParameterType.PARAMETER_BOOL_ARRAY, bool_array_value=[True, False]),
     [True, False], 'Boolean values are: [True, False]'),
    (ParameterValue(type=ParameterType.PARAMETER_INTEGER_ARRAY, integer_array_value=[1, 2]),
     [1, 2], 'Integer values are: [1, 2]'),
    (ParameterValue(type=ParameterType.PARAMETER_DOUBLE_ARRAY, double_array_value=[1.5, 2.5]),
     [1.5, 2.5], 'Double values are: [1.5, 2.5]'),
    (ParameterValue(type=ParameterType.PARAMETER_STRING_ARRAY, string_array_value=['a', 'b']),
     ['a', 'b'], "String values are: ['a', 'b']"),
]


@pytest.mark.parametrize('message, python, line', CASES,
                         ids=[f'type{case[0].type}' for case in CASES])
def test_each_type_converts_prints_and_dumps(message, python, line):
    value = to_python(message)
    assert (value, type(value)) == (python, type(python))
    assert describe(message) == line
    assert describe(message, hide_type=True) == line.split(': ', 1)[1]
    dumped = dump_yaml('/n', {'p': value})
    assert dumped.startswith('/n:\n  ros__parameters:\n    p:')
    assert '!!' not in dumped  # no Python-specific YAML tags (bytes, array.array)


def test_unset_and_unknown_types_are_not_set():
    for kind in (ParameterType.PARAMETER_NOT_SET, 42):
        message = ParameterValue(type=kind)
        assert to_python(message) is None
        assert describe(message) is None
