"""ComposableNode: the description of a C++ component to load into a container.

The description can be built (launch files that merely define one still
load), but nothing in this clean room can run it: see ComposableNodeContainer.
"""
from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any


class ComposableNode:
    """Describe a composable node (package, plugin class, name, parameters, ...)."""

    def __init__(self, *, package: Any, plugin: Any, name: Any = None, namespace: Any = None,
                 parameters: Sequence[Any] | None = None,
                 remappings: Iterable[Any] | None = None,
                 extra_arguments: Sequence[Any] | None = None,
                 condition: Any = None) -> None:
        self.package = package
        self.node_plugin = plugin
        self.node_name = name
        self.node_namespace = namespace
        self.parameters = parameters
        self.remappings = remappings
        self.extra_arguments = extra_arguments
        self.condition = condition

    def __repr__(self) -> str:
        return f'ComposableNode(package={self.package!r}, plugin={self.node_plugin!r})'
