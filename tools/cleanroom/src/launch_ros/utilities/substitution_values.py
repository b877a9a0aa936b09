"""Evaluating one parameter value that may contain substitutions.

Defined in `launch_ros._support.substitution_values`, below the parameter descriptions.
"""
from .._support.substitution_values import (  # noqa: F401 - public home of these names
    evaluate_value,
    is_substitution_text,
    perform_text,
)
