"""Jazzy import path of PushEnvironment."""
from .scope_actions import PushEnvironment

__all__ = ['PushEnvironment']
