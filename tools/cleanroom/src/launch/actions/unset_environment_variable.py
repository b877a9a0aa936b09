"""Jazzy import path of UnsetEnvironmentVariable."""
from .environment_actions import UnsetEnvironmentVariable

__all__ = ['UnsetEnvironmentVariable']
