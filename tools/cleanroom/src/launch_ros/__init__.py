"""Clean-room implementation of the ROS 2 Jazzy `launch_ros` Python API.

Subpackages are imported on first attribute access so that
`import launch_ros; launch_ros.actions.Node(...)` works as in Jazzy while the
pure helpers (namespaces, parameter typing) stay importable without pulling
in the whole launch system.
"""
from __future__ import annotations

import importlib
from types import ModuleType

_SUBMODULES = (
    'actions', 'descriptions', 'event_handlers', 'events', 'parameter_descriptions',
    'parameters_type', 'remap_rule_type', 'ros_adapters', 'substitutions', 'utilities',
)

__all__ = list(_SUBMODULES)


def __getattr__(name: str) -> ModuleType:
    if name in _SUBMODULES:
        return importlib.import_module('.' + name, __name__)
    raise AttributeError(f'module {__name__!r} has no attribute {name!r}')
