"""ComposableNodeContainer and LoadComposableNodes: not available in the clean room.

Composable nodes are C++ plugins loaded by rclcpp_components into a
container process; this environment has rclpy only.  Both actions can be
constructed (so a launch file with a disabled container still loads) and
raise a clear error when they would run.
"""
from __future__ import annotations

from typing import Any

from launch import Action, LaunchContext

UNAVAILABLE = ('{what}: composable (C++) nodes need a full ROS 2 install '
               '(rclcpp_components and a component container); this clean-room '
               'launch_ros runs only standalone executables. Start the node with '
               'launch_ros.actions.Node(package=..., executable=...) instead, or use a '
               'machine with ROS 2 Jazzy installed.')


class ComposableNodesUnavailableError(RuntimeError):
    """Raised when a launch tries to run composable nodes without ROS 2 installed."""


def _describe(value: Any) -> str:
    if value is None or isinstance(value, str):
        return repr(value)
    parts = value if isinstance(value, (list, tuple)) else [value]
    return ' + '.join(p if isinstance(p, str) else p.describe() for p in parts)


class ComposableNodeContainer(Action):
    """A component container; raises ComposableNodesUnavailableError when executed."""

    def __init__(self, *, name: Any, namespace: Any, package: Any = None,
                 executable: Any = None,
                 composable_node_descriptions: list[Any] | None = None,
                 **kwargs: Any) -> None:
        condition = kwargs.pop('condition', None)
        super().__init__(condition=condition)
        self.__name = name
        self.composable_node_descriptions = composable_node_descriptions or []

    def execute(self, context: LaunchContext) -> list[Any] | None:
        raise ComposableNodesUnavailableError(
            UNAVAILABLE.format(what=f'ComposableNodeContainer {_describe(self.__name)}'))


class LoadComposableNodes(Action):
    """Load components into a running container; raises when executed."""

    def __init__(self, *, composable_node_descriptions: list[Any], target_container: Any,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.composable_node_descriptions = composable_node_descriptions
        self.__target = target_container

    def execute(self, context: LaunchContext) -> list[Any] | None:
        target = getattr(self.__target, 'name', None) or self.__target
        raise ComposableNodesUnavailableError(
            UNAVAILABLE.format(what=f'LoadComposableNodes into {_describe(target)}'))


# Shown in reprs (`ros2 launch -p` prints them) under the module names Jazzy uses.
LoadComposableNodes.__module__ = 'launch_ros.actions.load_composable_nodes'
