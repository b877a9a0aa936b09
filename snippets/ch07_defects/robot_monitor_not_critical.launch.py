"""A planted defect for lesson 7.3: robot.launch.py whose safety monitor is not critical.

A copy of capstone_bringup's robot.launch.py with one change: the event
handler that shuts the launch down when the safety monitor exits is gone.
Everything starts, is wired and drives exactly as in the real file; only
when the safety monitor dies does the difference show: the launch goes on
as if nothing had happened, though nothing passes the controller's
commands on to the turtle any more and nobody is told.  Planted as
launch/robot.launch.py in a copy of capstone_bringup, it must make the
capstone's launch_testing test fail.
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import (DeclareLaunchArgument, EmitEvent, LogInfo, OpaqueFunction,
                            RegisterEventHandler)
from launch.events import matches_action
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from launch_ros.substitutions import FindPackageShare
from lifecycle_msgs.msg import Transition

CONFIG = PathJoinSubstitution([FindPackageShare('capstone_bringup'), 'config'])


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
        # (the defect: no handler for the safety monitor's exit here)
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
