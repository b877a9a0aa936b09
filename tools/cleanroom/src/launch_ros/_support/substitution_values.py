"""Evaluating one parameter value that may contain substitutions.

The typing rules themselves live in `parameter_values` (pure); this module
decides which parts of a value are substitution text and which are Python
values:

- a Substitution, or a list made only of Substitutions and strings with at
  least one Substitution, is *one* text (golden 15:
  `[TextSubstitution(text='robot_'), LaunchConfiguration('sim')]` -> "robot_true");
- any other list is a parameter array whose items are evaluated one by one;
- everything else is a Python value and keeps its type.
"""
from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch import LaunchContext, Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from .parameter_values import (
    coerce_text,
    coerce_value,
    homogeneous,
    is_list_type,
    list_item_type,
    plain_python_value,
)


def is_substitution_text(value: Any) -> bool:
    """True for a Substitution or a str/Substitution list holding at least one Substitution."""
    if isinstance(value, Substitution):
        return True
    if isinstance(value, (list, tuple)) and value:
        return (all(isinstance(item, (str, Substitution)) for item in value)
                and any(isinstance(item, Substitution) for item in value))
    return False


def perform_text(context: LaunchContext, value: Any) -> str:
    """Run the substitutions of a (list of) substitutions and strings into one string."""
    return perform_substitutions(context, normalize_to_list_of_substitutions(value))


def _evaluate_item(context: LaunchContext, item: Any, item_type: Any) -> Any:
    if is_substitution_text(item):
        return coerce_text(perform_text(context, item), item_type)
    if isinstance(item, (list, tuple)):
        raise TypeError(f'nested lists are not valid parameter values: {item!r}')
    return coerce_value(plain_python_value(item), item_type)


def evaluate_value(context: LaunchContext, value: Any, value_type: Any = None) -> Any:
    """Evaluate a parameter value to what goes into the node's parameter file."""
    if isinstance(value, (list, tuple)) and is_list_type(value_type):
        item_type = list_item_type(value_type)
        return [_evaluate_item(context, item, item_type) for item in value]
    if is_substitution_text(value):
        return coerce_text(perform_text(context, value), value_type)
    if isinstance(value, (list, tuple)):
        items = [_evaluate_item(context, item, None) for item in value]
        return coerce_value(_uniform(items), value_type)
    return coerce_value(plain_python_value(value), value_type)


def _uniform(items: Sequence[Any]) -> list[Any]:
    """Arrays are homogeneous in ROS (see homogeneous); items of substitutions that
    evaluated to different types are Jazzy's ValueError."""
    uniform = homogeneous(items)
    if uniform is None:
        raise ValueError('The output list is not uniform')
    return uniform
