"""Jazzy import path of Shutdown."""
from .event_handler_actions import Shutdown

__all__ = ['Shutdown']
