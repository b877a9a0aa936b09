"""Jazzy import path of UnregisterEventHandler."""
from .event_handler_actions import UnregisterEventHandler

__all__ = ['UnregisterEventHandler']
