"""Which parameters a ROS 2 parameter file gives a node of a given name.

A file maps node names to `ros__parameters:` blocks.  A node name key may be
fully qualified (`/robot1/controller`), relative (`controller`, which means
`/controller`), nested by namespace (`robot1: controller: ...`), or use the
wildcards `*` (one name token) and `/**` (any number of tokens).  Nested
parameter mappings become dotted names (`sensors.lidar.topic`).
"""
from __future__ import annotations

import fnmatch
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

PARAMETERS_KEY = 'ros__parameters'


@dataclass(frozen=True)
class FileBlock:
    """One `ros__parameters` block: the node name pattern it is for, and its values."""

    pattern: str
    parameters: dict[str, Any]

    @property
    def is_wildcard(self) -> bool:
        return '*' in self.pattern

    def matches(self, node_name: str) -> bool:
        return _match(self.pattern.strip('/').split('/'), node_name.strip('/').split('/'))


class ParameterFileError(ValueError):
    """The file cannot be read as a parameter file (message names the file)."""


def read_blocks(path: str | Path) -> list[FileBlock]:
    """Every `ros__parameters` block of the file, in file order."""
    try:
        data = yaml.safe_load(Path(path).read_text(encoding='utf-8'))
    except OSError as error:
        raise ParameterFileError(f'{path}: cannot read the parameter file ({error.strerror})') \
            from None
    except yaml.YAMLError as error:
        raise ParameterFileError(f'{path}: not valid YAML: {error}') from None
    if not isinstance(data, dict):
        raise ParameterFileError(f'{path}: a parameter file is a mapping of node names')
    blocks: list[FileBlock] = []
    _collect(data, [], blocks, path)
    return blocks


def _collect(mapping: dict, keys: list[str], blocks: list[FileBlock], path: str | Path) -> None:
    for key, value in mapping.items():
        if key == PARAMETERS_KEY:
            if not keys:
                raise ParameterFileError(f'{path}: {PARAMETERS_KEY} needs a node name above it')
            pattern = '/' + '/'.join(part.strip('/') for part in keys)
            blocks.append(FileBlock(pattern, flatten(value or {})))
        elif isinstance(value, dict):
            _collect(value, [*keys, str(key)], blocks, path)


def flatten(parameters: dict, prefix: str = '') -> dict[str, Any]:
    """Nested mappings -> dotted names, as a node sees them."""
    flat: dict[str, Any] = {}
    for key, value in parameters.items():
        name = f'{prefix}{key}'
        if isinstance(value, dict):
            flat.update(flatten(value, name + '.'))
        else:
            flat[name] = value
    return flat


def _match(pattern: list[str], name: list[str]) -> bool:
    if not pattern:
        return not name
    head, rest = pattern[0], pattern[1:]
    if head == '**':
        return any(_match(rest, name[skip:]) for skip in range(len(name) + 1))
    return bool(name) and fnmatch.fnmatchcase(name[0], head) and _match(rest, name[1:])
