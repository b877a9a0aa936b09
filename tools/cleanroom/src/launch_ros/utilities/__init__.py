"""Helpers shared by launch_ros actions.

Modules and the functions they hold share names (as in Jazzy), so the
functions are imported here eagerly: `launch_ros.utilities.evaluate_parameters`
is the function, not the module.
"""
from .evaluate_parameters import evaluate_parameter_dict, evaluate_parameters
from .namespace_utils import make_namespace_absolute, prefix_namespace
from .normalize_parameters import normalize_parameter_dict, normalize_parameters
from .normalize_remap_rule import normalize_remap_rule, normalize_remap_rules
from .track_node_names import add_node_name, get_node_name_count

__all__ = [
    'add_node_name', 'evaluate_parameter_dict', 'evaluate_parameters', 'get_node_name_count',
    'make_namespace_absolute', 'normalize_parameter_dict', 'normalize_parameters',
    'normalize_remap_rule', 'normalize_remap_rules', 'prefix_namespace',
]
