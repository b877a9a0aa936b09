"""`speccheck snapshot`: a spec written from the running graph, to start a spec from a
system that works (then tighten it by hand: rates, ranges, arguments).

It records what the running check can verify: each node with the parameters it
has as read (type and value), and each topic with its type, publishers and
subscribers, seen as `speccheck.graph` sees it (hidden nodes and topics, /rosout
and /parameter_events left out), so `speccheck live` meets it on the same system.
"""
from __future__ import annotations

import math
import re
import time
from array import array
from pathlib import Path
from typing import Any

import yaml

from speccheck import values
from speccheck.graph import GraphSnapshot, read_parameters
from speccheck.graph import graph as read_graph
from speccheck.launcher import Launch
from speccheck.ros_error import RosError
from speccheck.schema import FQN_PATTERN, SPEC_SCHEMA

#: Seconds the graph must stay the same before a launched system counts as up.
QUIET = 2.0

_PARAMETER_NAME = re.compile(SPEC_SCHEMA['properties']['nodes']['additionalProperties']
                             ['properties']['parameters']['propertyNames']['pattern'])
_TYPE = re.compile(SPEC_SCHEMA['properties']['topics']['additionalProperties']
                   ['properties']['type']['pattern'])
_NAME = re.compile(FQN_PATTERN)


class SnapshotError(RuntimeError):
    """Nothing to write a spec from (no nodes in the graph)."""


def build_spec(graph: GraphSnapshot, parameters: dict[str, dict[str, Any] | str],
               description: str) -> tuple[dict, list[str]]:
    """The spec data of `graph`, with `parameters` (node -> name -> value, or why they
    could not be read), and notes on what was left out and why."""
    notes: list[str] = []
    nodes: dict[str, Any] = {}
    for node in graph.nodes:
        if not _NAME.match(node):
            notes.append(f'node {node}: a name a spec cannot hold')
            continue
        read = parameters.get(node, {})
        if isinstance(read, str):
            notes.append(f'node {node}: parameters not read: {read}')
            nodes[node] = None
            continue
        nodes[node] = {'parameters': _parameters(node, read, notes)} if read else None
    topics: dict[str, Any] = {}
    for name, topic in graph.topics.items():
        if not _NAME.match(name):
            notes.append(f'topic {name}: a name a spec cannot hold')
            continue
        body: dict[str, Any] = {}
        if len(topic.types) == 1 and _TYPE.match(topic.types[0]):
            body['type'] = topic.types[0]
        else:
            notes.append(f'topic {name}: type {topic.type!r} not recorded')
        for key, names in (('publishers', topic.publishers), ('subscribers', topic.subscribers)):
            kept = [node for node in names if node in nodes]
            if kept:
                body[key] = kept
        topics[name] = body
    data: dict[str, Any] = {'description': description, 'nodes': nodes}
    if topics:
        data['topics'] = topics
    return data, notes


def _parameters(node: str, read: dict[str, Any], notes: list[str]) -> dict[str, dict]:
    result = {}
    for name, value in read.items():
        value = value.tolist() if isinstance(value, array) else value
        kind = values.ros_type(value)
        if not _PARAMETER_NAME.match(name):
            notes.append(f'node {node}: parameter {name}: a name a spec cannot hold')
        elif kind is None:
            notes.append(f'node {node}: parameter {name}: unset or of no single type')
        elif isinstance(value, float) and not math.isfinite(value):
            result[name] = {'type': kind}  # nan equals nothing: the type only
        else:
            kind = 'string_array' if kind == 'array' else kind  # empty: any array type
            result[name] = {'type': kind, 'value': list(value) if isinstance(value, tuple)
                            else value}
    return result


def to_yaml(data: dict, notes: list[str]) -> str:
    """The spec file's text: a header saying where it came from, notes as comments."""
    header = ['# Written by `speccheck snapshot` from the running graph: what it verifies',
              '# is what ran then. Tighten it by hand (rates, ranges, package/executable,',
              '# launch arguments): docs/reference/spec-files.md.']
    header += [f'# left out: {note}' for note in notes]
    body = yaml.safe_dump(data, sort_keys=False, allow_unicode=True, width=100)
    return '\n'.join(header) + '\n' + body


def take(description: str = 'Snapshot of the running system') -> tuple[dict, list[str]]:
    """The spec of the system running now."""
    seen = read_graph()
    if not seen.nodes:
        raise SnapshotError('no nodes in the ROS graph: is the system running, in this '
                            'ROS_DOMAIN_ID?')
    parameters: dict[str, dict[str, Any] | str] = {}
    for node in seen.nodes:
        try:
            parameters[node] = read_parameters(node)
        except RosError as error:
            parameters[node] = str(error)
    return build_spec(seen, parameters, description)


def settled_graph(timeout: float, quiet: float = QUIET) -> None:
    """Wait until the graph (nodes and endpoints) has not changed for `quiet` seconds,
    or `timeout` seconds have passed: a launch starts its nodes over a while."""
    deadline = time.monotonic() + timeout
    last, since = None, time.monotonic()
    while time.monotonic() < deadline:
        now = read_graph()
        seen = (now.nodes, tuple((t.name, t.publishers, t.subscribers)
                                 for t in now.topics.values()))
        if seen != last:
            last, since = seen, time.monotonic()
        elif now.nodes and time.monotonic() - since >= quiet:
            return
        time.sleep(0.25)


def snapshot_launch(launch_file: str | Path | tuple[str, str] | None,
                    arguments: dict[str, str] | None = None, *,
                    timeout: float = 20.0) -> tuple[dict, list[str]]:
    """Start `launch_file` (if given; a path or (package, file)), wait for its graph
    to settle, take the snapshot and stop it; without one, the running system's."""
    if launch_file is None:
        return take()
    words = launch_file if isinstance(launch_file, tuple) else (str(launch_file),)
    shown = Path(words[-1]).name + ''.join(f' {k}:={v}' for k, v in (arguments or {}).items())
    with Launch(*words, arguments=arguments):
        settled_graph(timeout)
        return take(f'Snapshot of {shown}')
