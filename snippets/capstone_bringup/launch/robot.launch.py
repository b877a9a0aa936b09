"""One robot: its nodes in the namespace of its turtle.

    ros2 launch capstone_bringup robot.launch.py robot:=turtle2

Data flow (all names relative, so inside /turtle2 they are /turtle2/...):
turtlesim's pose -> wall_sensor -> wall_reading -> safety_monitor;
pose -> pose_estimator -> estimated_pose -> patrol_planner -> goal ->
controller -> cmd_vel_nav (remapped) -> safety_monitor -> cmd_vel -> turtlesim.
The planner's status and the safety stops go to the mission recorder.

Parameters come in two layers: config/defaults.yaml, then the robot's own
file (robot_params, by default config/<robot>.yaml), which wins.
The safety monitor is critical: when it exits, the whole launch shuts
down.  The wall sensor is not: launch starts it again (respawn).  The
mission recorder is a lifecycle node, configured and then activated.

The nodes are made in an OpaqueFunction, with the robot's name as plain
text: the event handlers run later, outside the scope of an include that
set `robot` (capstone.launch.py includes this file once per robot), where
LaunchConfiguration('robot') no longer exists.
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import (DeclareLaunchArgument, EmitEvent, LogInfo, OpaqueFunction,
                            RegisterEventHandler)
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown, matches_action
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from launch_ros.substitutions import FindPackageShare
from lifecycle_msgs.msg import Transition

CONFIG = PathJoinSubstitution([FindPackageShare('capstone_bringup'), 'config'])



def unless_stopping(*entities):
    """An on_exit that does nothing once the launch is stopping: the process then
    exited because of that, and a second Shutdown is an error on Jazzy when the
    launch runs a ROS adapter (a LifecycleNode): 'Cannot shutdown a ROS adapter
    that is not running'."""
    return lambda _event, context: None if context.is_shutdown else list(entities)

def robot_system(context: LaunchContext) -> list:
    """The robot's nodes and event handlers, for the robot the arguments name."""
    robot = LaunchConfiguration('robot').perform(context)
    parameters = [PathJoinSubstitution([CONFIG, 'defaults.yaml']).perform(context),
                  LaunchConfiguration('robot_params').perform(context)]

    def robot_node(executable: str, **options) -> Node:
        return Node(package='capstone_robot', executable=executable, namespace=robot,
                    parameters=parameters, output='screen', **options)

    safety_monitor = robot_node('safety_monitor')
    recorder = LifecycleNode(package='capstone_robot', executable='mission_recorder',
                             name='mission_recorder', namespace=robot,
                             parameters=parameters, output='screen')
    return [
        # Not critical: a sensor that crashes comes back after a second (meanwhile
        # the safety monitor, without readings, holds the robot still).
        robot_node('wall_sensor', respawn=True, respawn_delay=1.0),
        robot_node('pose_estimator'),
        robot_node('patrol_planner'),
        robot_node('controller', remappings=[('cmd_vel', 'cmd_vel_nav')]),
        safety_monitor,
        # Critical: without the safety monitor nothing stops the robot at a wall.
        RegisterEventHandler(OnProcessExit(
            target_action=safety_monitor,
            on_exit=unless_stopping(
                LogInfo(msg=f'The safety monitor of {robot} exited: shutting down'),
                EmitEvent(event=Shutdown(reason=f'the safety monitor of {robot} exited'))),
        )),
        recorder,
        # Lifecycle: configure now; activate once configuring has succeeded.
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=recorder, start_state='configuring', goal_state='inactive',
            entities=[LogInfo(msg=f'Mission recorder of {robot} configured: activating'),
                      EmitEvent(event=ChangeState(
                          lifecycle_node_matcher=matches_action(recorder),
                          transition_id=Transition.TRANSITION_ACTIVATE))],
        )),
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(recorder),
                                    transition_id=Transition.TRANSITION_CONFIGURE)),
    ]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='turtle1',
                              description='The turtle to drive; also the namespace'),
        DeclareLaunchArgument('robot_params',
                              default_value=[CONFIG, '/', LaunchConfiguration('robot'), '.yaml'],
                              description="The robot's own parameter file (over defaults.yaml)"),
        OpaqueFunction(function=robot_system),
    ])
