"""Jazzy import path of SetEnvironmentVariable."""
from .environment_actions import SetEnvironmentVariable

__all__ = ['SetEnvironmentVariable']
