"""Evaluate normalized parameters against a launch context.

The result is a list of `pathlib.Path` (parameter files), `(name, value)`
tuples (single `Parameter`s) and flat `{name: value}` dicts, in the order
the launch file gave them.
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

EvaluatedParameter = Path | tuple[str, Any] | dict[str, Any]


def _key_part(context: LaunchContext, part: Any) -> str:
    return part if isinstance(part, str) else perform_text(context, part)


def evaluate_parameter_dict(context: LaunchContext,
                            parameters: NormalizedParameterDict) -> dict[str, Any]:
    """Substitute names and values; nested names are joined with '.'."""
    evaluated: dict[str, Any] = {}
    for name_parts, value in parameters.items():
        name = '.'.join(_key_part(context, part) for part in name_parts)
        evaluated[name] = value.evaluate(context)
    return evaluated


def evaluate_parameters(context: LaunchContext,
                        parameters: Sequence[NormalizedParameter]) -> list[EvaluatedParameter]:
    evaluated: list[EvaluatedParameter] = []
    for entry in parameters:
        if isinstance(entry, descriptions.ParameterFile):
            evaluated.append(entry.evaluate(context))
        elif isinstance(entry, descriptions.Parameter):
            evaluated.append(entry.evaluate(context))
        else:
            evaluated.append(evaluate_parameter_dict(context, entry))
    return evaluated
