"""Typing of ROS parameter values, free of launch imports.

Defined in `launch_ros._support.parameter_values`, below the parameter descriptions.
"""
from .._support.parameter_values import (  # noqa: F401 - public home of these names
    ParameterScalarTypes,
    ScalarValue,
    coerce_text,
    coerce_value,
    flatten_parameters,
    format_parameter_argument,
    is_list_type,
    list_item_type,
    plain_python_value,
    yaml_typed,
)
