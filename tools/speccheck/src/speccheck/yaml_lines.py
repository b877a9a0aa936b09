"""Load YAML and remember the line of every value, so that errors can say where.

PyYAML's composer already knows each node's position; we build plain Python
data from its node tree and keep a map from the path of each value (keys
and list indices, as jsonschema reports them) to its 1-based line.  Duplicate
keys are an error here: PyYAML would silently keep the last one.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

#: path of a value (mapping keys and list indices) -> 1-based line number
LineMap = dict[tuple, int]


class YamlError(ValueError):
    """The file is not valid YAML (or repeats a key); the message names file and line."""


def load_with_lines(path: str | Path) -> tuple[Any, LineMap]:
    """Parse `path`; return its data and the line of every key, item and value."""
    text = Path(path).read_text(encoding='utf-8')
    loader = yaml.SafeLoader(text)
    try:
        root = loader.get_single_node()
        lines: LineMap = {}
        data = _build(loader, root, (), lines, path) if root is not None else None
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        where = f'{path}:{mark.line + 1}' if mark else str(path)
        raise YamlError(f'{where}: YAML syntax error: {error.problem or error}') from None
    finally:
        loader.dispose()
    return data, lines


def _build(loader: yaml.SafeLoader, node: yaml.Node, here: tuple, lines: LineMap,
           path: str | Path) -> Any:
    lines.setdefault(here, node.start_mark.line + 1)
    if isinstance(node, yaml.MappingNode):
        loader.flatten_mapping(node)  # resolves `<<:` merge keys
        result = {}
        for key_node, value_node in node.value:
            key = loader.construct_object(key_node, deep=True)
            if key in result:
                raise YamlError(f'{path}:{key_node.start_mark.line + 1}: duplicate key '
                                f'{key!r} (first at line {lines[(*here, key)]})')
            lines[(*here, key)] = key_node.start_mark.line + 1
            result[key] = _build(loader, value_node, (*here, key), lines, path)
        return result
    if isinstance(node, yaml.SequenceNode):
        return [_build(loader, item, (*here, index), lines, path)
                for index, item in enumerate(node.value)]
    return loader.construct_object(node, deep=True)


def line_of(lines: LineMap, at: tuple) -> int | None:
    """The line of `at`, or of its nearest enclosing value that has one."""
    for end in range(len(at), -1, -1):
        if at[:end] in lines:
            return lines[at[:end]]
    return None
