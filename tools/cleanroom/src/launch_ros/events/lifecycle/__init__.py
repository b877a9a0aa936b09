"""Lifecycle events: ChangeState (a request) and StateTransition (a report)."""
from ..lifecycle_node_matchers import matches_node_name
from .change_state import ChangeState
from .state_transition import StateTransition

__all__ = ['ChangeState', 'StateTransition', 'matches_node_name']
