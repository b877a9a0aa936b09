"""The JSON schema of a spec file: spec.schema.json beside this module (see
docs/reference/spec-files.md).

The schema is a file rather than Python data so that editors (the YAML
language server's `# yaml-language-server: $schema=...`) and other tools
validate a spec with exactly what speccheck uses.  Every mapping forbids
unknown keys, so that a typo (`publisher:` for `publishers:`) is an error
rather than a requirement silently not checked.
"""
from __future__ import annotations

import json
from importlib import resources

#: The spec file's schema (JSON Schema draft 2020-12).
SPEC_SCHEMA: dict = json.loads(
    resources.files('speccheck').joinpath('spec.schema.json').read_text(encoding='utf-8'))

#: A fully qualified ROS name: /node, /ns/node, /ns/topic.
FQN_PATTERN: str = SPEC_SCHEMA['properties']['nodes']['propertyNames']['pattern']

#: Parameter types by their ROS names (rcl_interfaces/msg/ParameterType).
PARAMETER_TYPES: list[str] = (SPEC_SCHEMA['properties']['nodes']['additionalProperties']
                              ['properties']['parameters']['additionalProperties']
                              ['properties']['type']['enum'])
