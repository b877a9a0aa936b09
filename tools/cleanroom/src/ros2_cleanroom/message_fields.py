"""Filling a message from YAML data, as `ros2 topic pub` does; no ROS graph needed.

Each key names a field.  A nested message takes a mapping (or, for a time
`now`, for a header `auto`: the current time); a list of messages takes a
list of mappings; any other value is converted with the field's own Python
type (`str([1, 2])`, `int(1.5)`, `float('abc')` failing).  Errors are the
exceptions Python raises (an unknown field: AttributeError).
"""
from __future__ import annotations

import array
import importlib
from collections.abc import Callable
from typing import Any

import yaml
from rosidl_parser.definition import AbstractNestedType, NamespacedType

TIME_TYPE = 'builtin_interfaces.msg.Time'
HEADER_TYPE = 'std_msgs.msg.Header'


def _qualified(msg: Any) -> str:
    return f'{type(msg).__module__.rsplit(".", 1)[0].replace("._", ".")}.{type(msg).__name__}'


def _is_message(value: Any) -> bool:
    return hasattr(value, 'get_fields_and_field_types')


def set_message_fields(msg: Any, values: dict[str, Any],
                       now: Callable[[], Any] | None = None) -> None:
    """Set `msg`'s fields from `values` (a mapping), recursively.

    `now()` gives a builtin_interfaces Time for the `now` and `auto` keywords.
    """
    slot_types = dict(zip(msg.get_fields_and_field_types(), msg.SLOT_TYPES, strict=True))
    for name, value in values.items():
        current = getattr(msg, name)
        setattr(msg, name, _field_value(current, value, slot_types.get(name), now))


def _field_value(current: Any, value: Any, slot_type: Any,
                 now: Callable[[], Any] | None) -> Any:
    if _is_message(current):
        return _message_value(current, value, now)
    if isinstance(slot_type, AbstractNestedType) and \
            isinstance(slot_type.value_type, NamespacedType):
        element_type = type(current[0]) if len(current) else _import(slot_type.value_type)
        items = []
        for item in value:
            element = element_type()
            items.append(_message_value(element, item, now))
        return items
    if isinstance(current, (list, tuple, array.array)) or hasattr(current, 'tolist'):
        return value
    if type(value) is type(current):
        return value
    return type(current)(value)


def _message_value(current: Any, value: Any, now: Callable[[], Any] | None) -> Any:
    kind = _qualified(current)
    if now is not None and kind == TIME_TYPE and value == 'now':
        return now()
    if now is not None and kind == HEADER_TYPE and value == 'auto':
        current.stamp = now()
        return current
    if not isinstance(value, dict):
        raise TypeError(f"Value '{value}' is expected to be a dictionary but is a "
                        f'{type(value).__name__}')
    set_message_fields(current, value, now)
    return current


def _import(namespaced: NamespacedType) -> type:
    module = importlib.import_module('.'.join(namespaced.namespaces))
    return getattr(module, namespaced.name)


def fill_from_yaml(msg: Any, text: str) -> None:
    """Set `msg`'s fields from the YAML mapping `text`, as `service call` and
    `action send_goal` take their request or goal; raises what each reports."""
    values = yaml.safe_load(text)
    if not isinstance(values, dict):
        raise TypeError(f"Value '{values}' is expected to be a dictionary but is a "
                        f'{type(values).__name__}')
    set_message_fields(msg, values)
