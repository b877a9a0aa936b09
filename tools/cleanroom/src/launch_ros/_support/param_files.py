"""Temporary parameter files (`launch_params_*`) and their removal.

Nodes get parameter dicts through `--params-file`, as in Jazzy. As observed
on Jazzy, the file of a node's parameter dicts stays in the temporary folder
after the launch (nobody removes it), while the file a
`ParameterFile(allow_substs=True)` writes is removed at shutdown: only the
latter is remembered here; `remove_temporary_files()` is called from an
OnShutdown handler, and an `atexit` hook catches whatever a crashed or
interrupted launch left.
"""
from __future__ import annotations

import atexit
import os
import tempfile
import threading
from collections.abc import Hashable, Mapping
from typing import Any

import yaml

TEMP_PREFIX = 'launch_params_'

_lock = threading.Lock()
_created: dict[Hashable, list[str]] = {}


class _Dumper(yaml.SafeDumper):
    """Safe YAML that writes tuples as plain sequences (rcl reads no tags)."""


_Dumper.add_representer(tuple, _Dumper.represent_list)


def parameters_document(node_key: str, params: Mapping[str, Any]) -> dict[str, Any]:
    """The YAML structure rcl expects: {node_key: {ros__parameters: {...}}}."""
    return {node_key: {'ros__parameters': dict(params)}}


def _write(text: str) -> str:
    with tempfile.NamedTemporaryFile(mode='w', prefix=TEMP_PREFIX, delete=False) as handle:
        handle.write(text)
        return handle.name


def write_temporary_file(text: str, owner: Hashable = None) -> str:
    """Write text to a fresh `launch_params_*` file and remember it for cleanup.

    `owner` (a launch's key, see `remove_temporary_files`) lets two launches
    in one process clean up only their own files.
    """
    path = _write(text)
    with _lock:
        _created.setdefault(owner, []).append(path)
    return path


def write_parameters_file(node_key: str, params: Mapping[str, Any]) -> str:
    """Dump already-typed, already-flattened parameters for one node key into a
    `launch_params_*` file that stays after the launch, as Jazzy's does."""
    return _write(yaml.dump(parameters_document(node_key, params), Dumper=_Dumper,
                            default_flow_style=False, allow_unicode=True))


def temporary_files(owner: Hashable = None) -> list[str]:
    """Files of `owner` (all owners if None) not yet removed, for tests and diagnostics."""
    with _lock:
        if owner is None:
            return [path for paths in _created.values() for path in paths]
        return list(_created.get(owner, []))


def remove_temporary_file(path: str) -> None:
    """Delete one file written here and forget it (ParameterFile.cleanup)."""
    with _lock:
        for paths in _created.values():
            if path in paths:
                paths.remove(path)
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass


def remove_temporary_files(owner: Hashable = None) -> None:
    """Delete the files of `owner` (of everyone if None); missing files are fine."""
    with _lock:
        if owner is None:
            paths = [path for group in _created.values() for path in group]
            _created.clear()
        else:
            paths = _created.pop(owner, [])
    for path in paths:
        try:
            os.unlink(path)
        except FileNotFoundError:
            pass


atexit.register(remove_temporary_files)
