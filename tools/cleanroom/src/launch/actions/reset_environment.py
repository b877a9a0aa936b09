"""Jazzy import path of ResetEnvironment."""
from .scope_actions import ResetEnvironment

__all__ = ['ResetEnvironment']
