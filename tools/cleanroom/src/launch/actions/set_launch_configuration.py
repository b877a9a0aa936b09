"""Jazzy import path of SetLaunchConfiguration."""
from .launch_configuration_actions import SetLaunchConfiguration

__all__ = ['SetLaunchConfiguration']
