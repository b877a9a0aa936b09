"""Load a Python launch file and call its generate_launch_description()."""
from __future__ import annotations

import itertools
import os
import sys
import types

from ..launch_description import LaunchDescription

_counter = itertools.count(1)


class InvalidPythonLaunchFileError(Exception):
    """The Python launch file lacks generate_launch_description()."""


def load_python_launch_file_as_module(python_launch_file_path: str) -> types.ModuleType:
    """Execute the file as a fresh module (no bytecode is written next to it)."""
    stem = os.path.basename(python_launch_file_path).split('.')[0] or 'launch_file'
    name = f'launch_file_{next(_counter)}_{stem}'
    with open(python_launch_file_path, 'rb') as f:
        source = f.read()
    code = compile(source, python_launch_file_path, 'exec', dont_inherit=True)
    module = types.ModuleType(name)
    module.__file__ = python_launch_file_path
    sys.modules[name] = module  # dataclasses and pickling look modules up by name
    exec(code, module.__dict__)
    return module


def get_launch_description_from_python_launch_file(
        python_launch_file_path: str) -> LaunchDescription:
    """Return what the file's generate_launch_description() returns."""
    module = load_python_launch_file_as_module(python_launch_file_path)
    if not hasattr(module, 'generate_launch_description'):
        raise InvalidPythonLaunchFileError(
            f"launch file at '{python_launch_file_path}' does not contain the required "
            "function 'generate_launch_description()'")
    return module.generate_launch_description()
