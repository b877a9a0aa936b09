"""Jazzy import path of PopLaunchConfigurations."""
from .scope_actions import PopLaunchConfigurations

__all__ = ['PopLaunchConfigurations']
