"""Exercise 6.14.1: the dock watch system, version 3 (one robot in its namespace).

    ros2 launch my_ws_exercises ex614_dock_watch.launch.py
    ros2 launch my_ws_exercises ex614_dock_watch.launch.py robot:=rover

A copy of dock_watch_pkg's dock_watch_v2.launch.py, which meets version 2 of
the specification.  Version 3 adds one requirement:

R9. A launch argument `robot` (default `scout`) names the robot, and every
    node runs in the namespace it names, so its topics do too
    (/scout/battery_sim publishes /scout/battery_state, ...).

TODO: meet R9 and keep every other requirement met.  The spec of version 3
is dock_watch_pkg's specs/dock_watch_robot.spec.yaml.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    arguments = [
        DeclareLaunchArgument('battery_rate', default_value='5.0',
                              description='Battery states per second (Hz)'),
        DeclareLaunchArgument('dock_x', default_value='0.0', description='Dock x in map (m)'),
        DeclareLaunchArgument('dock_y', default_value='0.0', description='Dock y in map (m)'),
        DeclareLaunchArgument('low_threshold', default_value='0.25',
                              description='Charge (0.05 to 0.95) at or below which the '
                                          'battery is low'),
        # TODO (R9): the argument robot
    ]

    def number(argument: str) -> ParameterValue:
        """A launch argument as a double, so `battery_rate:=5` is 5.0, not the integer 5."""
        return ParameterValue(LaunchConfiguration(argument), value_type=float)

    # TODO (R9): every node in the namespace named by robot
    nodes = [
        Node(package='dock_watch_pkg', executable='battery_sim', name='battery_sim',
             parameters=[{'publish_rate': number('battery_rate')}]),
        Node(package='dock_watch_pkg', executable='battery_monitor', name='battery_monitor',
             parameters=[{'low_threshold': number('low_threshold')}]),
        Node(package='dock_watch_pkg', executable='dock_planner', name='dock_planner',
             parameters=[{'dock_x': number('dock_x'), 'dock_y': number('dock_y'),
                          'frame_id': 'map'}]),
    ]
    return LaunchDescription(arguments + nodes)
