"""LifecycleNode driven to 'active' by ChangeState / OnStateTransition, checked with get_state."""
import threading

import lifecycle_msgs.msg
import lifecycle_msgs.srv
import pytest
from launch.actions import EmitEvent, OpaqueFunction, RegisterEventHandler, TimerAction
from launch.events import Shutdown, matches_action
from launch_ros.actions import LifecycleNode, LifecycleTransition
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState, StateTransition, matches_node_name
from rclhelpers.services import call_service
from ros2_cleanroom.cli_node import cli_node

PKG = 'lr_test_pkg'
T = lifecycle_msgs.msg.Transition


def query_state(service: str) -> str:
    """Ask get_state from a separate rclpy context, as an outside tool would: through
    rclhelpers.call_service, the one copy labkit and the clean room share (issue 13)."""
    with cli_node('lr_state_probe') as node:
        response = call_service(node, lifecycle_msgs.srv.GetState, service,
                                lifecycle_msgs.srv.GetState.Request(), timeout=10.0)
    assert response is not None, f'{service} did not answer'
    return response.current_state.label


def transitions_recorder(node, seen):
    def record(context):
        event = context.locals.event
        assert isinstance(event, StateTransition) and event.action is node
        seen.append((event.start_state, event.goal_state))

    return RegisterEventHandler(OnStateTransition(
        target_lifecycle_node=node, entities=[OpaqueFunction(function=record)]))


def probe_then_shutdown(service, states):
    def probe(context):
        states.append(query_state(service))
        return [EmitEvent(event=Shutdown(reason='checked'))]

    return OpaqueFunction(function=probe)


def test_change_state_events_drive_node_to_active(test_package, run_launch):
    node = LifecycleNode(package=PKG, executable='lifecycle_talker', name='lc_talker',
                         namespace='lr')
    seen, states = [], []
    record = run_launch([
        node,
        transitions_recorder(node, seen),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=node, goal_state='inactive',
            entities=[EmitEvent(event=ChangeState(
                lifecycle_node_matcher=matches_action(node),
                transition_id=T.TRANSITION_ACTIVATE))])),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=node, start_state='activating', goal_state='active',
            entities=[probe_then_shutdown('/lr/lc_talker/get_state', states)])),
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                    transition_id=T.TRANSITION_CONFIGURE)),
        # a hang guard, not a speed limit: a loaded CI box once took over 15 s
        TimerAction(period=60.0, actions=[EmitEvent(event=Shutdown(reason='timeout'))]),
    ])
    assert record.returncode == 0
    assert states == ['active']
    assert seen == [('unconfigured', 'configuring'), ('configuring', 'inactive'),
                    ('inactive', 'activating'), ('activating', 'active')]
    assert node.node_name == '/lr/lc_talker'
    assert not [t.name for t in threading.enumerate()
                if t.name == 'launch_ros_adapter' or t.name.startswith('lifecycle ')]
    assert record.node_cmd('lc_talker')[1:] == [
        '--ros-args', '-r', '__node:=lc_talker', '-r', '__ns:=/lr']


def test_lifecycle_transition_action_walks_the_chain(test_package, run_launch):
    node = LifecycleNode(package=PKG, executable='lifecycle_talker', name='walker',
                         namespace='')
    states = []
    run_launch([
        node,
        LifecycleTransition(lifecycle_node_names=['/walker'],
                            transition_ids=[T.TRANSITION_CONFIGURE, T.TRANSITION_ACTIVATE]),
        RegisterEventHandler(OnStateTransition(
            matcher=lambda e: isinstance(e, StateTransition) and e.goal_state == 'active',
            entities=[probe_then_shutdown('/walker/get_state', states)])),
        # a hang guard, not a speed limit: a loaded CI box once took over 15 s
        TimerAction(period=60.0, actions=[EmitEvent(event=Shutdown(reason='timeout'))]),
    ])
    assert states == ['active']


def test_refused_transition_is_logged(test_package, run_launch, capfd):
    node = LifecycleNode(package=PKG, executable='lifecycle_talker', name='refuser',
                         namespace='lr', arguments=['fail_configure'])
    states = []
    run_launch([
        node,
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_node_name('/lr/refuser'),
                                    transition_id=T.TRANSITION_CONFIGURE)),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=node, start_state='configuring', goal_state='unconfigured',
            entities=[TimerAction(period=0.3, actions=[
                probe_then_shutdown('/lr/refuser/get_state', states)])])),
        # a hang guard, not a speed limit: a loaded CI box once took over 15 s
        TimerAction(period=60.0, actions=[EmitEvent(event=Shutdown(reason='timeout'))]),
    ])
    out = capfd.readouterr()
    assert states == ['unconfigured']
    assert ("Failed to make transition 'TRANSITION_CONFIGURE' for LifecycleNode '/lr/refuser'"
            in out.out + out.err)


def test_change_state_rejects_unknown_transition():
    with pytest.raises(ValueError, match="transition_id of '42'"):
        ChangeState(lifecycle_node_matcher=lambda action: True, transition_id=42)


def test_lifecycle_node_requires_name_and_namespace():
    with pytest.raises(TypeError):
        LifecycleNode(package=PKG, executable='lifecycle_talker', name='x')


def test_a_second_shutdown_with_the_ros_adapter_running_is_an_error(test_package, run_launch):
    """Observed on Jazzy (lesson 7.2, two critical processes exiting): with a
    LifecycleNode the launch process runs a ROS adapter, every Shutdown event
    shuts it down, and the second one ends the launch with exit code 1:
    `[ERROR] [launch]: Caught exception in launch (see debug for traceback):
    Cannot shutdown a ROS adapter that is not running`."""
    node = LifecycleNode(package=PKG, executable='lifecycle_talker', name='lc_twice',
                         namespace='lr')

    def shut_down_twice(_context):
        return [EmitEvent(event=Shutdown(reason='first')),
                EmitEvent(event=Shutdown(reason='second'))]

    result = run_launch([
        node,
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=node, goal_state='inactive',
            entities=[OpaqueFunction(function=shut_down_twice)])),
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                    transition_id=T.TRANSITION_CONFIGURE)),
        TimerAction(period=60.0, actions=[EmitEvent(event=Shutdown(reason='timeout'))]),
    ])
    assert ('[ERROR] [launch]: Caught exception in launch (see debug for traceback): '
            'Cannot shutdown a ROS adapter that is not running') in result.output
    assert result.returncode == 1
