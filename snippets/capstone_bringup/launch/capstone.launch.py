"""The whole capstone: the simulator and robot_count robots.

    ros2 launch capstone_bringup capstone.launch.py robot_count:=2
    ros2 launch capstone_bringup capstone.launch.py sim:=false robot_count:=1

sim:=true starts turtlesim and spawns the turtles (sim.launch.py); with
sim:=false the robots drive turtles that already exist (a turtlesim or a
robot started elsewhere).  Each robot is robot.launch.py in its own
namespace, turtle1, turtle2, ...; each include sits in a scoped group so
that one robot's arguments never leak into the next one's.  A critical
node's exit shuts everything down (the handlers live next to those nodes,
in sim.launch.py and robot.launch.py); this file logs why.  With
sim:=false the simulator is not this launch's process, so no handler can
see it end: a watchdog node (sim_watchdog) watches the ROS graph for
/turtlesim and exits when it is gone, and its exit shuts the system down.
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import (DeclareLaunchArgument, EmitEvent, GroupAction,
                            IncludeLaunchDescription, LogInfo, OpaqueFunction,
                            RegisterEventHandler)
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit, OnShutdown
from launch.events import Shutdown
from launch.launch_description_sources import PythonLaunchDescriptionSource
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

def launch_file(name: str) -> PythonLaunchDescriptionSource:
    return PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('capstone_bringup'), 'launch', name]))


def robots(context: LaunchContext) -> list[GroupAction]:
    """robot.launch.py once per robot, each in a scoped group of its own."""
    text = LaunchConfiguration('robot_count').perform(context)
    if not text.isdigit() or not 1 <= int(text) <= MAX_ROBOTS:
        raise ValueError(f"robot_count must be a whole number from 1 to {MAX_ROBOTS}, "
                         f"got '{text}'")
    return [GroupAction(scoped=True, actions=[IncludeLaunchDescription(
                launch_file('robot.launch.py'),
                launch_arguments={'robot': f'turtle{number}'}.items())])
            for number in range(1, int(text) + 1)]


def generate_launch_description():
    # sim:=false: the simulator runs elsewhere; when it is gone, this node exits.
    sim_watchdog = Node(package='capstone_robot', executable='sim_watchdog',
                        name='sim_watchdog', output='screen',
                        condition=UnlessCondition(LaunchConfiguration('sim')))
    return LaunchDescription([
        DeclareLaunchArgument('sim', default_value='true',
                              description='Start turtlesim (true) or drive existing turtles'),
        DeclareLaunchArgument('robot_count', default_value='2',
                              description=f'How many robots (1 to {MAX_ROBOTS})'),
        IncludeLaunchDescription(
            launch_file('sim.launch.py'),
            launch_arguments={'robot_count': LaunchConfiguration('robot_count')}.items(),
            condition=IfCondition(LaunchConfiguration('sim'))),
        OpaqueFunction(function=robots),
        sim_watchdog,
        RegisterEventHandler(OnProcessExit(
            target_action=sim_watchdog,
            on_exit=unless_stopping(
                LogInfo(msg='The simulator watchdog exited: no world left, shutting down'),
                EmitEvent(event=Shutdown(reason='the simulator is gone'))),
        )),
        RegisterEventHandler(OnShutdown(
            on_shutdown=lambda event, context: LogInfo(
                msg=f'Capstone shutting down: {event.reason}'))),
    ])
