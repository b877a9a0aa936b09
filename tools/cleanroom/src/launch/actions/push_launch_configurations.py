"""Jazzy import path of PushLaunchConfigurations."""
from .scope_actions import PushLaunchConfigurations

__all__ = ['PushLaunchConfigurations']
