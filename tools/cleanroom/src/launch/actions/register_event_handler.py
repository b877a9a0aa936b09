"""Jazzy import path of RegisterEventHandler."""
from .event_handler_actions import RegisterEventHandler

__all__ = ['RegisterEventHandler']
