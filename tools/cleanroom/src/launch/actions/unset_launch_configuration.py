"""Jazzy import path of UnsetLaunchConfiguration."""
from .launch_configuration_actions import UnsetLaunchConfiguration

__all__ = ['UnsetLaunchConfiguration']
