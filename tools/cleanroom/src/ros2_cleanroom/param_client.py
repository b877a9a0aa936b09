"""Calls to a node's parameter services (rcl_interfaces), for `ros2 param`."""
from __future__ import annotations

from rcl_interfaces.msg import Parameter, ParameterValue, SetParametersResult
from rcl_interfaces.srv import GetParameters, ListParameters, SetParameters
from rclhelpers.services import call_service
from rclpy.node import Node


class ParameterServiceError(RuntimeError):
    """The node did not answer a parameter service call."""

    def __init__(self, target: str) -> None:
        super().__init__(f"Exception while calling service of node '{target}': "
                         'the service did not respond')


def list_names(node: Node, target: str, prefixes: list[str] | None = None) -> list[str]:
    """All parameter names of `target` (recursively), sorted."""
    request = ListParameters.Request(prefixes=list(prefixes or []), depth=0)
    response = call_service(node, ListParameters, f'{target}/list_parameters', request)
    if response is None:
        raise ParameterServiceError(target)
    return sorted(response.result.names)


def get_values(node: Node, target: str, names: list[str]) -> list[ParameterValue]:
    """The values of `names` on `target`, in the same order."""
    response = call_service(node, GetParameters, f'{target}/get_parameters',
                            GetParameters.Request(names=list(names)))
    if response is None:
        raise ParameterServiceError(target)
    return list(response.values)


def set_value(node: Node, target: str, name: str, value: ParameterValue) -> SetParametersResult:
    """Set one parameter; the node's own result (successful, reason) is returned."""
    request = SetParameters.Request(parameters=[Parameter(name=name, value=value)])
    response = call_service(node, SetParameters, f'{target}/set_parameters', request)
    if response is None or not response.results:
        raise ParameterServiceError(target)
    return response.results[0]
