"""Composable nodes need rclcpp_components: the actions load, and fail clearly when run."""
import pytest
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
from launch_ros.actions.composable_nodes import ComposableNodesUnavailableError
from launch_ros.descriptions import ComposableNode

ERROR_PREFIX = '[ERROR] [launch]: Caught exception in launch (see debug for traceback): '


def container():
    return ComposableNodeContainer(
        name='my_container', namespace='', package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='demo', plugin='demo::Talker', name='talker')])


def test_container_fails_with_a_clear_message(run_launch, capfd):
    record = run_launch([container()])
    out = capfd.readouterr()
    assert record.returncode == 1
    assert (ERROR_PREFIX + "ComposableNodeContainer 'my_container': composable (C++) nodes "
            'need a full ROS 2 install') in out.out + out.err


def test_load_composable_nodes_fails_when_executed():
    action = LoadComposableNodes(target_container='/my_container', composable_node_descriptions=[
        ComposableNode(package='demo', plugin='demo::Talker')])
    with pytest.raises(ComposableNodesUnavailableError, match='need a full ROS 2 install'):
        action.execute(None)


def test_disabled_container_is_harmless(run_launch):
    from launch.conditions import IfCondition

    action = ComposableNodeContainer(name='c', namespace='', package='rclcpp_components',
                                     executable='component_container',
                                     condition=IfCondition('false'))
    assert run_launch([action]).returncode == 0
