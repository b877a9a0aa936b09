"""Load a Python launch file and call its generate_launch_description()."""
from __future__ import annotations

import importlib.machinery
import importlib.util
import types

from ..launch_description import LaunchDescription


class InvalidPythonLaunchFileError(Exception):
    """The Python launch file lacks generate_launch_description()."""


def load_python_launch_file_as_module(python_launch_file_path: str) -> types.ModuleType:
    """Execute the file as a fresh module named `python_launch_file`, with Python's own
    source loader: as in Jazzy, it is not put in sys.modules, and its bytecode goes to
    __pycache__/ next to the file as any imported module's would."""
    loader = importlib.machinery.SourceFileLoader('python_launch_file', python_launch_file_path)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)  # __file__ is the path as given, as in Jazzy
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
