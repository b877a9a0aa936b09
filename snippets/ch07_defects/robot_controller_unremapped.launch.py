"""A planted defect for lesson 7.3: robot.launch.py whose controller is not remapped.

A copy of capstone_bringup's robot.launch.py with one change: the
controller's remapping of cmd_vel to cmd_vel_nav is gone.  Every node starts
and nothing is logged as wrong, but the controller now publishes straight
on the turtle's cmd_vel, beside the safety monitor: the monitor's
cmd_vel_nav has no publisher, and nothing stands between the controller
and the wall.  Lesson 7.3 finds the cause with the tools of lesson 6.7.
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
        robot_node('controller'),  # the defect: its cmd_vel is the turtle's
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
