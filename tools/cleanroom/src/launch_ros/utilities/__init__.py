"""Helpers shared by launch_ros actions.

Pure helpers (namespaces, parameter typing, command lines) import nothing
from `launch`; the ones that evaluate substitutions are loaded on first use.
"""
from __future__ import annotations

import importlib
from typing import Any

from .namespace_utils import make_namespace_absolute, prefix_namespace

_LAZY = {
    'normalize_parameters': 'launch_ros.utilities.normalize_parameters',
    'normalize_parameter_dict': 'launch_ros.utilities.normalize_parameters',
    'evaluate_parameters': 'launch_ros.utilities.evaluate_parameters',
    'evaluate_parameter_dict': 'launch_ros.utilities.evaluate_parameters',
    'normalize_remap_rule': 'launch_ros.utilities.normalize_remap_rule',
    'normalize_remap_rules': 'launch_ros.utilities.normalize_remap_rule',
    'add_node_name': 'launch_ros.utilities.track_node_names',
    'get_node_name_count': 'launch_ros.utilities.track_node_names',
}

__all__ = ['make_namespace_absolute', 'prefix_namespace', *_LAZY]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f'module {__name__!r} has no attribute {name!r}')
