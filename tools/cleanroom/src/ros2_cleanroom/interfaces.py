"""Find interface classes by name and turn messages into plain data / YAML.

`rosidl_runtime_py` is not among the PyPI wheels, so the verbs use this small
equivalent: `pkg/msg/Type` -> the generated Python class, and a message ->
ordered Python data that PyYAML prints the way `ros2 topic echo` does.
"""
from __future__ import annotations

import array
import importlib
from typing import Any

import yaml

TRUNCATE_LENGTH = 128


def import_interface(name: str, kind: str = 'msg') -> type:
    """`std_msgs/msg/String` (or `std_msgs/String`) -> the Python class.

    Raises ValueError with a message naming the bad type when the name is
    malformed or the package/type cannot be imported.
    """
    parts = name.split('/')
    if len(parts) == 2:
        parts = [parts[0], kind, parts[1]]
    if len(parts) != 3 or not all(parts) or parts[1] != kind:
        raise ValueError(f"The passed {_kind_word(kind)} type '{name}' is invalid")
    package, _, type_name = parts
    try:
        module = importlib.import_module(f'{package}.{kind}')
        return getattr(module, type_name)
    except (ImportError, AttributeError):
        raise ValueError(f"The passed {_kind_word(kind)} type '{name}' is invalid") from None


def _kind_word(kind: str) -> str:
    return {'msg': 'message', 'srv': 'service', 'action': 'action'}.get(kind, kind)


def message_to_data(msg: Any, truncate_length: int | None = TRUNCATE_LENGTH,
                    no_arr: bool = False, no_str: bool = False) -> Any:
    """A message as dicts (in field order), lists and plain scalars.

    Long strings and arrays are cut to `truncate_length` items followed by
    '...', as `ros2 topic echo` does unless asked for the full length.
    """
    if hasattr(msg, 'get_fields_and_field_types'):
        data = {}
        for field in msg.get_fields_and_field_types():
            value = getattr(msg, field)
            if no_arr and _is_sequence(value):
                data[field] = f'<array type: {msg.get_fields_and_field_types()[field]}>'
            elif no_str and isinstance(value, str):
                data[field] = f'<string length: <{len(value)}>>'
            else:
                data[field] = message_to_data(value, truncate_length, no_arr, no_str)
        return data
    if _is_sequence(msg):
        items = list(msg)
        cut = truncate_length is not None and len(items) > truncate_length
        if cut:
            items = items[:truncate_length]
        values = [message_to_data(item, truncate_length, no_arr, no_str) for item in items]
        return values + ['...'] if cut else values
    if isinstance(msg, str):
        if truncate_length is not None and len(msg) > truncate_length:
            return msg[:truncate_length] + '...'
        return msg
    if isinstance(msg, bytes):
        return list(msg) if len(msg) != 1 else msg[0]
    return _plain_scalar(msg)


def message_to_csv(msg: Any, truncate_length: int | None = TRUNCATE_LENGTH,
                   no_arr: bool = False, no_str: bool = False) -> str:
    """The line `ros2 topic echo --csv` prints: every field in order, comma-separated.

    As rosidl_runtime_py does: nested messages and arrays are flattened into
    the line, an empty array still takes its (empty) place, strings are not quoted.
    """
    return _csv(message_to_data(msg, truncate_length, no_arr, no_str))


def _csv(data: Any) -> str:
    if isinstance(data, dict):
        return ','.join(_csv(value) for value in data.values())
    if isinstance(data, list):
        return ','.join(_csv(item) for item in data)
    return str(data)


def _is_sequence(value: Any) -> bool:
    if isinstance(value, (list, tuple, array.array)):
        return True
    # a numpy array, not one of its items (numpy scalars have tolist() too)
    return type(value).__module__ == 'numpy' and getattr(value, 'ndim', 0) > 0


def _plain_scalar(value: Any) -> Any:
    """numpy scalars -> Python scalars, so YAML prints them plainly."""
    if hasattr(value, 'item') and type(value).__module__ == 'numpy':
        value = value.item()
    return value


class _OrderedDumper(yaml.SafeDumper):
    """Dumps dicts in insertion (field) order and never wraps long lines."""


_OrderedDumper.add_representer(
    dict, lambda dumper, data: dumper.represent_mapping(
        'tag:yaml.org,2002:map', data.items(), flow_style=None))


def message_to_yaml(msg: Any, truncate_length: int | None = TRUNCATE_LENGTH,
                    no_arr: bool = False, no_str: bool = False,
                    flow_style: bool = False) -> str:
    """The YAML text `ros2 topic echo` prints for one message (ends in newline)."""
    data = message_to_data(msg, truncate_length, no_arr, no_str)
    return yaml.dump(data, Dumper=_OrderedDumper, default_flow_style=flow_style,
                     width=float('inf'), allow_unicode=True, sort_keys=False)
