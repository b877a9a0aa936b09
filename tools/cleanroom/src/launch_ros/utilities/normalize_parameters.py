"""Check and normalize `Node(parameters=[...])` when the launch file is loaded.

Each entry becomes one of (the shapes Jazzy returns):

- a `ParameterFile` (any entry that is not a dict, a ParameterFile or a
  Parameter is given to `ParameterFile(...)`, whose checks apply),
- a `Parameter`,
- a dict `{name: value}`, the name a tuple of substitutions ('a' ->
  `(TextSubstitution('a'),)`); nested dicts are flattened here, the parts of a
  name joined by `TextSubstitution('.')`.  Values:

  - a ParameterValue, a bool, int, float or bytes is kept as it is;
  - a str becomes one YAML text, `(TextSubstitution(yaml.dump(s)),)`, read back
    as that same str when evaluated;
  - a Substitution becomes `(sub,)`;
  - a list (any sequence) of numbers becomes a tuple, ints as floats if it holds
    floats; of bools a tuple of bools; of Substitutions and strs one flat tuple
    of substitutions (one text); of anything else a tuple of lists of
    substitutions, one per item (strs, bools and numbers as YAML text), whose
    types are checked when evaluated.
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import yaml
from launch import Substitution
from launch.substitutions import TextSubstitution
from launch.utilities import ensure_argument_type, normalize_to_list_of_substitutions

# Module import: parameter_descriptions imports this package (circular otherwise).
from .. import parameter_descriptions as descriptions

# {name (tuple of substitutions): normalized value}
NormalizedParameterDict = dict[tuple[Substitution, ...], Any]
NormalizedParameter = Any | NormalizedParameterDict

#: What a list item may be, in the order Jazzy names them in its error.
_ITEM_TYPES = (float, int, str, bool, str, Substitution, Iterable)
#: An item's kind, the first that matches (bool before int: a bool is an int too).
_ITEM_KINDS = (Substitution, str, bool, int, float, Sequence)


def _yaml_text(value: Any) -> list[Substitution]:
    return normalize_to_list_of_substitutions(yaml.dump(value))


def _normalize_parameter_array_value(value: Any) -> Any:
    """One parameter value, normalized as the module docstring says."""
    if isinstance(value, descriptions.ParameterValue):
        return value
    if isinstance(value, (bool, int, float, bytes)):
        return value
    if isinstance(value, str):
        return tuple(_yaml_text(value))
    if isinstance(value, Substitution):
        return (value,)
    if not isinstance(value, Sequence):
        raise TypeError(f'Unexpected type for parameter value {value!r}')
    kinds: set[type] = set()
    for item in value:
        ensure_argument_type(item, _ITEM_TYPES, 'subvalue')
        kind = next((kind for kind in _ITEM_KINDS if isinstance(item, kind)), None)
        if kind is None:
            raise RuntimeError(f'Failed to handle type {item!r}')
        kinds.add(list if kind is Sequence else kind)
    if kinds == {int}:
        return tuple(value)
    if kinds in ({float}, {int, float}):
        return tuple(float(item) for item in value)
    if kinds == {bool}:
        return tuple(value)
    if Substitution in kinds and kinds <= {Substitution, str}:
        return tuple(normalize_to_list_of_substitutions(value))
    return tuple(normalize_to_list_of_substitutions(item) if isinstance(item, (Substitution, list))
                 or (isinstance(item, Sequence) and not isinstance(item, str))
                 else _yaml_text(item) for item in value)


def normalize_parameter_dict(parameters: Mapping[Any, Any], *,
                             _prefix: Sequence[Substitution] | None = None
                             ) -> NormalizedParameterDict:
    """Flatten nested dicts; names become tuples of substitutions."""
    normalized: NormalizedParameterDict = {}
    for name, value in parameters.items():
        parts = tuple(normalize_to_list_of_substitutions(name))
        if _prefix:
            parts = (*_prefix, TextSubstitution(text='.'), *parts)
        if isinstance(value, Mapping):
            normalized.update(normalize_parameter_dict(value, _prefix=parts))
        else:
            normalized[parts] = _normalize_parameter_array_value(value)
    return normalized


def normalize_parameters(parameters: Sequence[Any]) -> tuple[NormalizedParameter, ...]:
    """Normalize the `parameters` argument of Node (see the module docstring); a
    tuple, as Jazzy returns."""
    if isinstance(parameters, str) or not isinstance(parameters, Sequence):
        raise TypeError(f'Expecting list of parameters, got {parameters}')
    normalized: list[NormalizedParameter] = []
    for entry in parameters:
        if isinstance(entry, (descriptions.ParameterFile, descriptions.Parameter)):
            normalized.append(entry)
        elif isinstance(entry, Mapping):
            normalized.append(normalize_parameter_dict(entry))
        else:
            normalized.append(descriptions.ParameterFile(entry))
    return tuple(normalized)
