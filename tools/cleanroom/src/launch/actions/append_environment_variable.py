"""Jazzy import path of AppendEnvironmentVariable."""
from .environment_actions import AppendEnvironmentVariable

__all__ = ['AppendEnvironmentVariable']
