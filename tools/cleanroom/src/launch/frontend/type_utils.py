"""Coerce the text of an attribute to the type a parse method asks for."""
from __future__ import annotations

from typing import Any

import yaml

_SCALARS = (bool, int, float, str)


def _is_list_type(data_type: Any) -> bool:
    return getattr(data_type, '__origin__', None) is list or data_type is list


def _list_item_type(data_type: Any) -> Any:
    args = getattr(data_type, '__args__', None)
    return args[0] if args else None


def infer_value(text: str) -> Any:
    """Type `text` as YAML would ('7' -> 7, 'yes' -> True, '[a, b]' -> ['a', 'b']).

    Anything YAML cannot read, or reads as something other than a scalar or a
    list of scalars, stays the text itself.
    """
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    if isinstance(value, _SCALARS):
        return value
    if isinstance(value, list) and all(isinstance(item, _SCALARS) for item in value):
        return value
    return text


def coerce_scalar(text: str, data_type: Any) -> Any:
    """Convert `text` to int/float/bool/str; ValueError when it does not fit."""
    if data_type is None:
        return infer_value(text)
    if data_type is str:
        return text
    if data_type is bool:
        lowered = text.lower()
        if lowered in ('true', 'false'):
            return lowered == 'true'
        raise ValueError(f"could not convert string to bool: '{text}'")
    if data_type in (int, float):
        return data_type(text)
    raise ValueError(f'unsupported attribute type: {data_type}')


def get_typed_value(value: Any, data_type: Any, can_be_str: bool = True) -> Any:
    """Coerce `value` (text, or a list of texts) to `data_type`.

    With `can_be_str` a text that does not fit is returned unchanged (Jazzy
    accepts e.g. scoped="maybe"); without it the ValueError propagates.
    """
    try:
        if _is_list_type(data_type):
            item_type = _list_item_type(data_type)
            items = value if isinstance(value, list) else [value]
            return [coerce_scalar(item, item_type) if isinstance(item, str) else item
                    for item in items]
        if isinstance(value, list):
            return [coerce_scalar(item, data_type) if isinstance(item, str) else item
                    for item in value]
        if not isinstance(value, str):
            return value
        return coerce_scalar(value, data_type)
    except ValueError:
        if can_be_str:
            return value
        raise


AllowedListTypes = (list[int], list[float], list[bool], list[str])
