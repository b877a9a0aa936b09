"""Jazzy import path of ResetLaunchConfigurations."""
from .scope_actions import ResetLaunchConfigurations

__all__ = ['ResetLaunchConfigurations']
