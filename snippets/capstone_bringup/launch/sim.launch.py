"""The simulator: turtlesim, and one more turtle for each robot after the first.

    ros2 launch capstone_bringup sim.launch.py robot_count:=2

turtlesim starts with turtle1; a spawner asks it for turtle2, turtle3, ...
at the pose in config/<turtle>.yaml.  The same file starts the real
turtlesim where it is installed and the book's headless one elsewhere: both
are `turtlesim turtlesim_node`.  Without turtlesim nothing can move, so its
exit ends the whole launch.
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import (DeclareLaunchArgument, EmitEvent, LogInfo, OpaqueFunction,
                            RegisterEventHandler)
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

MAX_ROBOTS = 4  # config/turtle1.yaml ... turtle4.yaml



def unless_stopping(*entities):
    """An on_exit that does nothing once the launch is stopping: the process then
    exited because of that, and a second Shutdown is an error on Jazzy when the
    launch runs a ROS adapter (a LifecycleNode): 'Cannot shutdown a ROS adapter
    that is not running'."""
    return lambda _event, context: None if context.is_shutdown else list(entities)

def robot_count(context: LaunchContext) -> int:
    """The argument robot_count as a number, or an error that says what is allowed."""
    text = LaunchConfiguration('robot_count').perform(context)
    if not text.isdigit() or not 1 <= int(text) <= MAX_ROBOTS:
        raise ValueError(f"robot_count must be a whole number from 1 to {MAX_ROBOTS}, "
                         f"got '{text}'")
    return int(text)


def spawners(context: LaunchContext) -> list[Node]:
    """One spawner per turtle after turtle1, in that turtle's namespace."""
    return [Node(package='capstone_robot', executable='spawner', namespace=f'turtle{number}',
                 parameters=[PathJoinSubstitution([FindPackageShare('capstone_bringup'),
                                                   'config', f'turtle{number}.yaml'])],
                 output='screen')
            for number in range(2, robot_count(context) + 1)]


def generate_launch_description():
    turtlesim = Node(package='turtlesim', executable='turtlesim_node', name='turtlesim',
                     output='screen')
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='1',
                              description=f'How many turtles (1 to {MAX_ROBOTS})'),
        # First, so that a bad robot_count stops the launch before anything starts;
        # a spawner waits for turtlesim's /spawn by itself.
        OpaqueFunction(function=spawners),
        turtlesim,
        RegisterEventHandler(OnProcessExit(
            target_action=turtlesim,
            on_exit=unless_stopping(
                LogInfo(msg='turtlesim exited: no world left, shutting down'),
                EmitEvent(event=Shutdown(reason='turtlesim exited'))),
        )),
    ])
