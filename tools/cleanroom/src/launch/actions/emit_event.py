"""Jazzy import path of EmitEvent."""
from .event_handler_actions import EmitEvent

__all__ = ['EmitEvent']
