"""A spec: the system a launch file is meant to bring up, read from a YAML file.

Format (all sections optional; docs/reference/spec-files.md has the details)::

    description: The range sensor and its filter
    nodes:
      /sensor_publisher:                 # fully qualified node name
        package: my_robot_pkg            # optional
        executable: sensor_publisher     # optional
        parameters:
          publish_rate: {type: double, value: 2.0}      # or min: / max:
    topics:
      /distance:
        type: std_msgs/msg/Float32
        publishers: [/sensor_publisher]
        subscribers: [/data_processor]
        rate: {min: 1.5, max: 2.5}       # Hz, measured by the running check
    arguments:                           # what the launch file must declare
      sim_mode: {default: 'true', choices: ['true', 'false']}
      robot_ns: {required: true}         # declared without a default

The file is validated against :data:`speccheck.schema.SPEC_SCHEMA` (the file
spec.schema.json); any error names the file and line.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import jsonschema

from speccheck.schema import SPEC_SCHEMA
from speccheck.yaml_lines import LineMap, YamlError, line_of, load_with_lines


class SpecError(ValueError):
    """A spec file that cannot be used; the message starts with `file:line:`."""


@dataclass(frozen=True)
class ParameterSpec:
    name: str
    type: str
    value: Any = None
    has_value: bool = False
    min: float | None = None
    max: float | None = None


@dataclass(frozen=True)
class NodeSpec:
    name: str
    package: str | None = None
    executable: str | None = None
    parameters: tuple[ParameterSpec, ...] | None = None


@dataclass(frozen=True)
class TopicSpec:
    name: str
    type: str | None = None
    publishers: tuple[str, ...] = ()
    subscribers: tuple[str, ...] = ()
    rate_min: float | None = None
    rate_max: float | None = None

    @property
    def has_rate(self) -> bool:
        return self.rate_min is not None or self.rate_max is not None


@dataclass(frozen=True)
class ArgumentSpec:
    name: str
    default: str | None = None
    required: bool = False
    choices: tuple[str, ...] | None = None


@dataclass(frozen=True)
class Spec:
    source: str
    description: str = ''
    nodes: tuple[NodeSpec, ...] = ()
    topics: tuple[TopicSpec, ...] = ()
    arguments: tuple[ArgumentSpec, ...] = ()
    lines: LineMap = field(default_factory=dict, compare=False, repr=False)

    def node(self, name: str) -> NodeSpec | None:
        return next((node for node in self.nodes if node.name == name), None)


def load_spec(path: str | Path) -> Spec:
    """Read and validate a spec file; raises SpecError naming file and line."""
    try:
        data, lines = load_with_lines(path)
    except FileNotFoundError:
        raise SpecError(f'{path}: no such spec file') from None
    except YamlError as error:
        raise SpecError(str(error)) from None
    if data is None:
        data = {}
    _validate(data, lines, path)
    return _build_spec(data, lines, str(path))


def _validate(data: Any, lines: LineMap, path: str | Path) -> None:
    validator = jsonschema.Draft202012Validator(SPEC_SCHEMA)
    errors = sorted(validator.iter_errors(data),
                    key=lambda e: (line_of(lines, tuple(e.absolute_path)) or 0, e.message))
    if not errors:
        return
    messages = [_describe(error, lines, path) for error in errors]
    raise SpecError('\n'.join(messages))


def _describe(error: jsonschema.ValidationError, lines: LineMap, path: str | Path) -> str:
    at = tuple(error.absolute_path)
    message = error.message
    if error.validator == 'additionalProperties' and isinstance(error.instance, dict):
        known = set(error.schema.get('properties', {}))
        unknown = [key for key in error.instance if key not in known]
        if unknown:
            at = (*at, unknown[0])
            allowed = ', '.join(sorted(known)) or 'none'
            message = f'unknown key {unknown[0]!r} (allowed here: {allowed})'
    elif 'propertyNames' in error.relative_schema_path:  # the key itself is wrong
        at = (*at, error.instance)
        message = (f'{error.instance!r} is not a valid name here (a fully qualified name '
                   'such as /robot1/lidar)' if error.schema.get('pattern', '').startswith('^(/')
                   else f'{error.instance!r} is not a valid name here ({error.message})')
    elif error.validator == 'not':
        message = _explain_not(error)
    where = '.'.join(str(part) for part in at) or 'top level'
    return f'{path}:{line_of(lines, at) or 1}: {where}: {message}'


def _explain_not(error: jsonschema.ValidationError) -> str:
    both = error.schema['not']['required']
    return f'give either {both[0]!r} or {both[1]!r}, not both'


def _as_text(value: Any) -> str:
    """Launch argument values are strings; YAML `true` or `2.0` mean 'true' and '2.0'."""
    if isinstance(value, bool):
        return 'true' if value else 'false'
    return str(value)


def _build_spec(data: dict, lines: LineMap, source: str) -> Spec:
    nodes = []
    for name, body in (data.get('nodes') or {}).items():
        body = body or {}
        parameters = body.get('parameters')
        if parameters is not None:
            parameters = tuple(
                ParameterSpec(pname, p['type'], p.get('value'), 'value' in p,
                              p.get('min'), p.get('max'))
                for pname, p in parameters.items())
        nodes.append(NodeSpec(name, body.get('package'), body.get('executable'), parameters))
    topics = [TopicSpec(name, body.get('type'), tuple(body.get('publishers', ())),
                        tuple(body.get('subscribers', ())),
                        (body.get('rate') or {}).get('min'), (body.get('rate') or {}).get('max'))
              for name, body in (data.get('topics') or {}).items()]
    arguments = []
    for name, body in (data.get('arguments') or {}).items():
        body = body or {}
        default = body.get('default')
        choices = body.get('choices')
        arguments.append(ArgumentSpec(
            name, None if default is None else _as_text(default), bool(body.get('required')),
            None if choices is None else tuple(_as_text(choice) for choice in choices)))
    return Spec(source, data.get('description', ''), tuple(nodes), tuple(topics),
                tuple(arguments), lines)
