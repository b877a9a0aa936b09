"""Actions of launch_ros."""
from .composable_nodes import (
    ComposableNodeContainer,
    ComposableNodesUnavailableError,
    LoadComposableNodes,
)
from .lifecycle_node import LifecycleNode
from .lifecycle_transition import LifecycleTransition
from .node import Node
from .push_ros_namespace import PushROSNamespace, PushRosNamespace
from .set_parameter import SetParameter
from .set_parameters_from_file import SetParametersFromFile
from .set_remap import SetRemap
from .set_use_sim_time import SetUseSimTime

__all__ = [
    'ComposableNodeContainer', 'ComposableNodesUnavailableError', 'LifecycleNode',
    'LifecycleTransition', 'LoadComposableNodes', 'Node', 'PushROSNamespace',
    'PushRosNamespace', 'SetParameter', 'SetParametersFromFile', 'SetRemap', 'SetUseSimTime',
]
