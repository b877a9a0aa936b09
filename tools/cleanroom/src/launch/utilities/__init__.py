"""Helpers shared by actions, substitutions and launch_ros."""
from .class_tools import is_a, is_a_subclass
from .create_future import create_future
from .ensure_argument_type import ensure_argument_type
from .normalize_to_list_of_substitutions import normalize_to_list_of_substitutions
from .perform_substitutions import perform_substitutions

__all__ = [
    'create_future',
    'ensure_argument_type',
    'is_a',
    'is_a_subclass',
    'normalize_to_list_of_substitutions',
    'perform_substitutions',
]
