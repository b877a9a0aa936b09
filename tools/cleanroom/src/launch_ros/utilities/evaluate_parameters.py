"""Evaluate normalized parameters against a launch context.

The result is a tuple of `pathlib.Path` (parameter files), the `Parameter`s
themselves and flat `{name: value}` dicts, in the order the launch file gave
them, as Jazzy returns it.  Values of a normalized dict (see
normalize_parameters) evaluate as Jazzy's do:

- a ParameterValue evaluates itself (a list stays a list);
- substitution text is read as YAML ('' stays ''); a YAML list must hold items
  of one type (that of the first), and becomes a tuple;
- a tuple of lists of substitutions is one YAML value per item, of one type;
- a tuple of Python values stays as it is; a scalar must be a float, int,
  str, bool or bytes.
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import yaml
from launch import LaunchContext, Substitution
from launch.utilities import ensure_argument_type, perform_substitutions

# Module import: parameter_descriptions imports this package (circular otherwise).
from .. import parameter_descriptions as descriptions
from .normalize_parameters import NormalizedParameter, NormalizedParameterDict

EvaluatedParameter = Path | descriptions.Parameter | dict[str, Any]

_STR_HINT = ('If the parameter is meant to be a string, try wrapping it in '
             'launch_ros.parameter_descriptions.ParameterValue(value, value_type=str)')
_ITEM_TYPES = (bool, int, float, str)


def _not_uniform(name: str) -> TypeError:
    return TypeError('Expected a non-empty sequence, with items of uniform type. Allowed '
                     'sequence item types are bool, int, float, str. Got inconsistent input '
                     f'for "{name}"')


def _uniform_items(name: str, items: Sequence[Any]) -> tuple[Any, ...]:
    """Items of one type, that of the first (so a bool may follow an int, a bool being
    an int in Python, but not the other way round), else Jazzy's TypeError."""
    if not items or not isinstance(items[0], _ITEM_TYPES):
        raise _not_uniform(name)
    first = type(items[0])
    if not all(isinstance(item, first) for item in items):
        raise _not_uniform(name)
    return tuple(items)


def _evaluate_text(context: LaunchContext, name: str, value: Sequence[Substitution]) -> Any:
    text = perform_substitutions(context, list(value))
    if text == '':
        return ''
    try:
        loaded = yaml.safe_load(text)
    except yaml.YAMLError:
        raise TypeError(f'Unable to parse the value of parameter {name} as yaml. '
                        f'{_STR_HINT}') from None
    if isinstance(loaded, list):
        return _uniform_items(name, loaded)
    if not isinstance(loaded, (bytes, *_ITEM_TYPES)):
        raise TypeError('Allowed value types are bytes, bool, int, float, str, Sequence[bool], '
                        'Sequence[int], Sequence[float], Sequence[str]. Got '
                        f'{type(loaded)} for "{name}". {_STR_HINT}')
    return loaded


def _evaluate_value(context: LaunchContext, name: str, value: Any) -> Any:
    if isinstance(value, descriptions.ParameterValue):
        return value.evaluate(context)
    if isinstance(value, tuple) and value:
        if isinstance(value[0], Substitution):
            return _evaluate_text(context, name, value)
        if isinstance(value[0], list):
            return _uniform_items(name, [
                yaml.safe_load(perform_substitutions(context, item)) for item in value])
        return value
    ensure_argument_type(value, (float, int, str, bool, bytes), 'value')
    return value


def evaluate_parameter_dict(context: LaunchContext,
                            parameters: NormalizedParameterDict) -> dict[str, Any]:
    """Substitute names and values (see the module docstring)."""
    evaluated: dict[str, Any] = {}
    for name_parts, value in parameters.items():
        name = perform_substitutions(context, list(name_parts))
        evaluated[name] = _evaluate_value(context, name, value)
    return evaluated


def evaluate_parameters(context: LaunchContext, parameters: Sequence[NormalizedParameter]
                        ) -> tuple[EvaluatedParameter, ...]:
    evaluated: list[EvaluatedParameter] = []
    for entry in parameters:
        if isinstance(entry, descriptions.ParameterFile):
            evaluated.append(entry.evaluate(context))
        elif isinstance(entry, descriptions.Parameter):
            evaluated.append(entry)  # Jazzy hands the Parameter on; Node evaluates it
        else:
            evaluated.append(evaluate_parameter_dict(context, entry))
    return tuple(evaluated)
