"""How `ros2 service echo` prints one service event, as observed on Jazzy.

It differs from `ros2 topic echo`: the event type is named
(`REQUEST_SENT`), `--no-arr` describes a sequence with its element type and
length, and `--flow-style` writes lists inline but mappings as blocks.
`--csv` prints the plain numbers, as topic echo does.
"""
from __future__ import annotations

import argparse
from typing import Any

import yaml
from rosidl_parser.definition import (
    AbstractNestedType,
    Array,
    BasicType,
    BoundedSequence,
    NamespacedType,
)
from service_msgs.msg import ServiceEventInfo

from ros2_cleanroom.interfaces import message_to_csv, message_to_data

EVENT_TYPES = {getattr(ServiceEventInfo, name): name for name in
               ('REQUEST_SENT', 'REQUEST_RECEIVED', 'RESPONSE_SENT', 'RESPONSE_RECEIVED')}


def _type_name(slot: Any) -> str:
    if isinstance(slot, NamespacedType):
        return '/'.join([*slot.namespaces, slot.name])
    if isinstance(slot, BasicType):
        return slot.typename
    return type(slot).__name__.lower()


def _describe(slot: AbstractNestedType, value: Any) -> str:
    """`--no-arr`'s text for an array or sequence field."""
    element = _type_name(slot.value_type)
    if isinstance(slot, Array):
        return f'<array type: {element}[{slot.size}]>'
    if isinstance(slot, BoundedSequence):
        element += f'[{slot.maximum_size}]'
    return f'<sequence type: {element}, length: {len(value)}>'


def _without_arrays(msg: Any, data: dict[str, Any]) -> dict[str, Any]:
    for field, slot in zip(msg.get_fields_and_field_types(), msg.SLOT_TYPES, strict=True):
        value = getattr(msg, field)
        if isinstance(slot, AbstractNestedType):
            data[field] = _describe(slot, value)
        elif hasattr(value, 'get_fields_and_field_types'):
            _without_arrays(value, data[field])
    return data


class _Dumper(yaml.SafeDumper):
    """Fields in order; `inline_lists` writes lists in flow style, mappings as blocks."""

    inline_lists = False


_Dumper.add_representer(dict, lambda dumper, data: dumper.represent_mapping(
    'tag:yaml.org,2002:map', data.items(), flow_style=False))
_Dumper.add_representer(list, lambda dumper, data: dumper.represent_sequence(
    'tag:yaml.org,2002:seq', data, flow_style=dumper.inline_lists or None))


class _FlowDumper(_Dumper):
    inline_lists = True


def format_event(msg: Any, args: argparse.Namespace) -> str:
    """The text printed for one event: YAML and its `---`, or one `--csv` line."""
    truncate = None if args.full_length else args.truncate_length
    if args.csv:
        return message_to_csv(msg, truncate, args.no_arr, args.no_str) + '\n'
    data = message_to_data(msg, truncate, False, args.no_str)
    if args.no_arr:
        _without_arrays(msg, data)
    info = data.get('info')
    if isinstance(info, dict) and info.get('event_type') in EVENT_TYPES:
        info['event_type'] = EVENT_TYPES[info['event_type']]
    text = yaml.dump(data, Dumper=_FlowDumper if args.flow_style else _Dumper,
                     default_flow_style=False, width=float('inf'), allow_unicode=True,
                     sort_keys=False)
    return text + '---\n'
