"""Events emitted or consumed by launch_ros actions."""
from . import lifecycle
from .lifecycle_node_matchers import matches_node_name

__all__ = ['lifecycle', 'matches_node_name']
