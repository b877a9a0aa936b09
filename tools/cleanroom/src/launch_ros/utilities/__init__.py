"""Helpers shared by launch_ros actions.

Modules and the functions they hold share names (as in Jazzy), so the
functions are imported here eagerly: `launch_ros.utilities.evaluate_parameters`
is the function, not the module.
"""
from .evaluate_parameters import evaluate_parameters
from .namespace_utils import (
    is_namespace_absolute,
    is_root_namespace,
    make_namespace_absolute,
    prefix_namespace,
)
from .normalize_parameters import normalize_parameters
from .normalize_remap_rule import normalize_remap_rule, normalize_remap_rules
from .track_node_names import add_node_name, get_node_name_count

# Jazzy's list, word for word: it names two functions the package does not hold
# (`from launch_ros.utilities import *` fails there with AttributeError, as in Jazzy).
__all__ = [
    'add_node_name', 'evaluate_parameters', 'evaluate_parameters_dict', 'get_node_name_count',
    'is_namespace_absolute', 'is_root_namespace', 'make_namespace_absolute',
    'normalize_parameters', 'normalize_parameters_dict', 'normalize_remap_rule',
    'normalize_remap_rules', 'prefix_namespace', 'to_parameters_list',
]
