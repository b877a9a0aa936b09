"""Jazzy import path of PopEnvironment."""
from .scope_actions import PopEnvironment

__all__ = ['PopEnvironment']
