"""Evaluate normalized parameters against a launch context.

The result is a tuple of `pathlib.Path` (parameter files), the `Parameter`s
themselves and flat `{name: value}` dicts, in the order the launch file gave
them, as Jazzy returns it: a list given as a plain Python value comes back as
a tuple (one typed from a substitution, e.g. `ParameterValue(..., value_type=
List[int])`, as the list YAML makes of it), and an empty one is refused.
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from launch import LaunchContext

# Module import: parameter_descriptions imports this package (circular otherwise).
from .. import parameter_descriptions as descriptions
from .normalize_parameters import NormalizedParameter, NormalizedParameterDict
from .substitution_values import perform_text

EvaluatedParameter = Path | descriptions.Parameter | dict[str, Any]
#: Jazzy's words for an empty list (it cannot tell the type of its items).
_SCALAR_TYPES = ("[<class 'float'>, <class 'int'>, <class 'str'>, <class 'bool'>, "
                 "<class 'bytes'>]")


def _key_part(context: LaunchContext, part: Any) -> str:
    return part if isinstance(part, str) else perform_text(context, part)


def evaluate_parameter_dict(context: LaunchContext,
                            parameters: NormalizedParameterDict) -> dict[str, Any]:
    """Substitute names and values; nested names are joined with '.'."""
    evaluated: dict[str, Any] = {}
    for name_parts, value in parameters.items():
        name = '.'.join(_key_part(context, part) for part in name_parts)
        evaluated[name] = _evaluate_value(context, value)
    return evaluated


def _evaluate_value(context: LaunchContext, value: descriptions.ParameterValue) -> Any:
    if isinstance(value.value, (list, tuple)) and not value.value:
        raise TypeError(f"Expected 'value' to be one of {_SCALAR_TYPES}, but got '()' of "
                        "type '<class 'tuple'>'")
    result = value.evaluate(context)
    # A plain list of values stays a sequence (a list of substitutions is one text).
    plain_list = isinstance(value.value, (list, tuple)) and isinstance(result, list)
    return tuple(result) if plain_list else result


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
