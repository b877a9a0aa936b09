"""Event handlers for launch_ros events."""
from .on_state_transition import OnStateTransition

__all__ = ['OnStateTransition']
