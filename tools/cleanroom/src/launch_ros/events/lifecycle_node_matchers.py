"""Predicates that pick a lifecycle node action, for ChangeState's matcher."""
from __future__ import annotations

from collections.abc import Callable
from typing import Any


def matches_node_name(node_name: str) -> Callable[[Any], bool]:
    """Match the action whose fully qualified node name is `node_name` ('/ns/name')."""
    return lambda action: getattr(action, 'node_name', None) == node_name
