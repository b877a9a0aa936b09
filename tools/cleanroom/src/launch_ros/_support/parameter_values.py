"""Typing of ROS parameter values, free of launch imports.

Two sources of values reach a node's parameters, and Jazzy types them
differently (goldens 02, 07, 13, 28 of the conformance suite):

- Python values written in the launch file keep their Python type: `'yes'`
  stays the string "yes", `ParameterValue('[1, 2, 3]')` stays a string.
- Text produced by substitutions is read as YAML 1.1, like a parameter file
  would be: `'007'` becomes 7, `'042'` (octal) becomes 34, `'true'` True.

`ParameterValue(..., value_type=T)` then checks or converts to `T`.
"""
from __future__ import annotations

import typing
from collections.abc import Mapping, Sequence
from typing import Any

import yaml

ScalarValue = bool | int | float | str | bytes
ParameterScalarTypes = (bool, int, float, str, bytes)


def homogeneous(items: Sequence[Any]) -> list | None:
    """``items`` as a ROS array, which holds one type: ints mixed with floats become
    floats; None when they mix any other types (each caller refuses that in the
    words Jazzy uses there)."""
    kinds = {type(item) for item in items}
    if kinds == {int, float}:
        return [float(item) for item in items]
    return list(items) if len(kinds) <= 1 else None


def _uniform_list(items: list) -> list | None:
    """A YAML list becomes a parameter array only if rcl could store it: scalars of
    one type (see homogeneous); nested lists, dicts and mixed types are refused."""
    if not items or not {type(item) for item in items} <= {bool, int, float, str}:
        return None
    return homogeneous(items)


def yaml_typed(text: str) -> Any:
    """Type substitution output by YAML 1.1; keep the text if ROS can't store the result."""
    try:
        loaded = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    if isinstance(loaded, (bool, int, float, str)):
        return loaded
    if isinstance(loaded, list):
        uniform = _uniform_list(loaded)
        if uniform is not None:
            return uniform
    return text


def _type_error(value: Any, value_type: Any) -> TypeError:
    return TypeError(f'value={value!r} is not an instance of {value_type}')


def list_item_type(value_type: Any) -> Any | None:
    """`List[int]` / `list[int]` -> int; `list` -> None (any item type)."""
    origin = typing.get_origin(value_type)
    if origin in (list, tuple, Sequence, list):
        args = typing.get_args(value_type)
        return args[0] if args else None
    return None


def is_list_type(value_type: Any) -> bool:
    return value_type in (list, tuple) or typing.get_origin(value_type) in (
        list, tuple, Sequence, list)


def coerce_value(value: Any, value_type: Any) -> Any:
    """Check a typed value against `value_type`, converting where ROS would.

    ints are accepted (and converted) where floats are expected; bools
    are not ints here although Python thinks so.  Raises TypeError with
    Jazzy's wording, e.g. "value='0.5' is not an instance of <class 'float'>".
    """
    if value_type is None:
        return value
    if is_list_type(value_type):
        if not isinstance(value, (list, tuple)):
            raise _type_error(value, value_type)
        item_type = list_item_type(value_type)
        try:
            return [coerce_value(item, item_type) for item in value]
        except TypeError:
            raise _type_error(value, value_type) from None
    if value_type is float and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    if value_type is int and isinstance(value, bool):
        raise _type_error(value, value_type)
    if not isinstance(value, value_type):
        raise _type_error(value, value_type)
    return value


def coerce_text(text: str, value_type: Any) -> Any:
    """Type substitution output for an explicit `value_type`.

    `str` keeps the text untouched (that is how '007' stays "007");
    other types read it as YAML first, so '1' is a valid float (1.0).
    """
    if value_type is None:
        return yaml_typed(text)
    if value_type is str:
        return text
    try:
        loaded = yaml.safe_load(text)
    except yaml.YAMLError:
        raise _type_error(text, value_type) from None
    try:
        return coerce_value(loaded, value_type)
    except TypeError:
        raise _type_error(text, value_type) from None


def plain_python_value(value: Any) -> Any:
    """Normalize a Python parameter value: tuples to lists, reject what ROS can't hold."""
    if isinstance(value, ParameterScalarTypes):
        return value
    if isinstance(value, (list, tuple)):
        return [plain_python_value(item) for item in value]
    raise TypeError(f'unsupported parameter value {value!r} of type {type(value)}')


def flatten_parameters(params: Mapping[str, Any], prefix: str = '') -> dict[str, Any]:
    """Nested dicts become dotted names, as rcl does for nested YAML maps."""
    flat: dict[str, Any] = {}
    for key, value in params.items():
        name = prefix + str(key)
        if isinstance(value, Mapping):
            flat.update(flatten_parameters(value, name + '.'))
        else:
            flat[name] = value
    return flat


def format_parameter_argument(name: str, value: Any) -> str:
    """`name:=value` for `-p`, rendered like Jazzy does (`use_sim_time:=True`)."""
    return f'{name}:={value}'
