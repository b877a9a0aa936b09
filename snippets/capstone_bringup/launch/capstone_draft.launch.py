# capstone_bringup/launch/capstone.launch.py
"""Top-level bringup: turtlesim (optional) + N robots, each in /turtleN.

    ros2 launch capstone_bringup capstone.launch.py                  # sim + 2 robots
    ros2 launch capstone_bringup capstone.launch.py robot_count:=3   # sim + 3 robots
    ros2 launch capstone_bringup capstone.launch.py sim:=false       # turtles already exist
"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, ExecuteProcess, GroupAction,
                            IncludeLaunchDescription, LogInfo, OpaqueFunction,
                            RegisterEventHandler, Shutdown)
from launch.event_handlers import OnProcessExit
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

PKG = 'capstone_bringup'
MIN_ROBOTS = 1
MAX_ROBOTS = 4

# With sim:=false, turtlesim is not our process, so we can't watch its exit.
# Instead: wait up to 30 s for /turtlesim to appear, then poll until it's gone.
# When this script ends, for either reason, the whole launch shuts down (R7).
SIM_WATCHDOG = (
    'for i in $(seq 1 30); do '
    '  ros2 node list 2>/dev/null | grep -qx /turtlesim && break; sleep 1; '
    'done; '
    'while ros2 node list 2>/dev/null | grep -qx /turtlesim; do sleep 2; done; '
    'echo "[capstone] /turtlesim is not running -> shutting down" >&2'
)


def _parse_bool(name, text):
    value = text.strip().lower()
    if value in ('true', '1', 'yes', 'on'):
        return True
    if value in ('false', '0', 'no', 'off'):
        return False
    raise ValueError(f"launch argument '{name}' must be true or false, got '{text}'")


def _parse_robot_count(text):
    try:
        count = int(text.strip())
    except ValueError:
        raise ValueError(f"launch argument 'robot_count' must be an integer, got '{text}'")
    if not MIN_ROBOTS <= count <= MAX_ROBOTS:
        raise ValueError(
            f"launch argument 'robot_count' must be between {MIN_ROBOTS} and "
            f"{MAX_ROBOTS}, got {count}")
    return count


def _is_turtlesim(action):
    """Match the turtlesim node started inside sim.launch.py."""
    if not isinstance(action, Node):
        return False
    try:
        if action.node_name == '/turtlesim':
            return True
    except RuntimeError:  # name not resolved yet / not set
        pass
    return (getattr(action, 'node_package', None) == 'turtlesim'
            and getattr(action, 'node_executable', None) == 'turtlesim_node')


def _launch_setup(context, *args, **kwargs):
    # Check the arguments first, so nothing starts if they are bad.
    sim = _parse_bool('sim', LaunchConfiguration('sim').perform(context))
    robot_count = _parse_robot_count(LaunchConfiguration('robot_count').perform(context))

    share = get_package_share_directory(PKG)
    launch_dir = os.path.join(share, 'launch')
    config_dir = os.path.join(share, 'config')
    robots = [f'turtle{i}' for i in range(1, robot_count + 1)]

    actions = [LogInfo(msg=f"[capstone] sim={sim}, robots: {', '.join(robots)}")]

    # R1 + R7: the simulator
    if sim:
        # Register before the simulator starts. It applies across the launch
        # tree, so it also sees the turtlesim node inside sim.launch.py.
        actions.append(RegisterEventHandler(OnProcessExit(
            target_action=_is_turtlesim,
            on_exit=[
                LogInfo(msg='[capstone] turtlesim exited -> shutting down'),
                Shutdown(reason='turtlesim exited'),
            ],
        )))
        actions.append(GroupAction(scoped=True, actions=[
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(launch_dir, 'sim.launch.py')),
                launch_arguments={'robot_count': str(robot_count)}.items(),
            ),
        ]))
    else:
        actions.append(ExecuteProcess(
            name='sim_watchdog',
            cmd=['bash', '-c', SIM_WATCHDOG],
            output='screen',
            on_exit=[Shutdown(reason='turtlesim not available')],
        ))

    # R2 + R7: one robot per turtle, each in its own namespace
    # (robot.launch.py sets the namespace and shuts down if its safety monitor exits).
    # scoped=True keeps each include's launch configurations, e.g. robot_params,
    # from carrying over into the next robot.
    for robot in robots:
        actions.append(GroupAction(scoped=True, actions=[
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(launch_dir, 'robot.launch.py')),
                launch_arguments={
                    'robot': robot,
                    'robot_params': os.path.join(config_dir, f'{robot}.yaml'),
                }.items(),
            ),
        ]))

    return actions


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument(
            'sim', default_value='true',
            description='Start turtlesim (false: turtles already exist, e.g. a turtlesim started elsewhere)'),
        DeclareLaunchArgument(
            'robot_count', default_value='2',
            description=f'Number of robots/turtles ({MIN_ROBOTS}..{MAX_ROBOTS})'),
        OpaqueFunction(function=_launch_setup),
    ])
