"""Check and normalize `Node(parameters=[...])` when the launch file is loaded.

Each entry becomes one of:

- a `ParameterFile` (from a path, a string or substitutions naming a file),
- a `Parameter`,
- a dict `{name parts (tuple): ParameterValue}`; nested dicts are flattened
  here, their key parts joined with '.' once the keys are substituted.

Errors say which entry is wrong, at load time rather than at start time.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from launch import Substitution

# Module import: parameter_descriptions imports this package (circular otherwise).
from .. import parameter_descriptions as descriptions

# {name parts: ParameterValue}; ParameterFile | Parameter | that dict.
NormalizedParameterDict = dict[tuple[Any, ...], Any]
NormalizedParameter = Any | NormalizedParameterDict


def _is_path_like(entry: Any) -> bool:
    if isinstance(entry, (str, Path, Substitution)):
        return True
    return (isinstance(entry, (list, tuple)) and bool(entry)
            and all(isinstance(item, (str, Substitution)) for item in entry))


def normalize_parameter_dict(parameters: Mapping[Any, Any],
                             _prefix: tuple[Any, ...] = ()) -> NormalizedParameterDict:
    """Flatten nested dicts and wrap every value in a ParameterValue."""
    normalized: NormalizedParameterDict = {}
    for key, value in parameters.items():
        if not isinstance(key, (str, Substitution, tuple, list)):
            raise TypeError(f'parameter names must be strings or substitutions, got {key!r}')
        name = _prefix + (list(key) if isinstance(key, (tuple, list)) else key,)
        if isinstance(value, Mapping):
            normalized.update(normalize_parameter_dict(value, name))
        elif isinstance(value, descriptions.ParameterValue):
            normalized[name] = value
        else:
            normalized[name] = descriptions.ParameterValue(value)
    return normalized


def normalize_parameters(parameters: Sequence[Any]) -> tuple[NormalizedParameter, ...]:
    """Normalize the `parameters` argument of Node (see the module docstring); a
    tuple, as Jazzy returns."""
    if isinstance(parameters, (str, Mapping)) or not isinstance(parameters, Sequence):
        raise TypeError(
            f"'parameters' must be a list of files, dicts or Parameter, got {parameters!r}")
    normalized: list[NormalizedParameter] = []
    for entry in parameters:
        if isinstance(entry, (descriptions.ParameterFile, descriptions.Parameter)):
            normalized.append(entry)
        elif isinstance(entry, Mapping):
            normalized.append(normalize_parameter_dict(entry))
        elif _is_path_like(entry):
            normalized.append(descriptions.ParameterFile(entry))
        else:
            raise TypeError(
                f"'parameters' entries must be a parameter file path, a dict or a "
                f'Parameter, got {entry!r} of type {type(entry).__name__}')
    return tuple(normalized)
