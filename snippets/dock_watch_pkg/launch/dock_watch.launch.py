"""Lesson 6.14: the dock watch system, built to specs/dock_watch.spec.yaml.

    ros2 launch dock_watch_pkg dock_watch.launch.py
    ros2 launch dock_watch_pkg dock_watch.launch.py battery_rate:=4.0 dock_x:=2.5 dock_y:=-1.0

battery_sim publishes the battery's state, battery_monitor says with every
reading whether it is low, dock_planner sends a dock goal when it turns low.
Each comment names the requirement (R1 to R7 of the lesson) a line meets.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    # [START arguments]
    arguments = [  # R7: the launch interface
        DeclareLaunchArgument('battery_rate', default_value='2.0',
                              description='Battery states per second (Hz)'),
        DeclareLaunchArgument('dock_x', default_value='0.0', description='Dock x in map (m)'),
        DeclareLaunchArgument('dock_y', default_value='0.0', description='Dock y in map (m)'),
    ]
    # [END arguments]

    def number(argument: str) -> ParameterValue:
        """A launch argument as a double, so `battery_rate:=5` is 5.0, not the integer 5."""
        return ParameterValue(LaunchConfiguration(argument), value_type=float)

    # [START nodes]
    nodes = [
        Node(package='dock_watch_pkg', executable='battery_sim', name='battery_sim',  # R1
             parameters=[{'publish_rate': number('battery_rate')}]),  # R2
        Node(package='dock_watch_pkg', executable='battery_monitor', name='battery_monitor',
             parameters=[{'low_threshold': 0.2}]),  # R4: a fraction, 20 % is 0.2
        Node(package='dock_watch_pkg', executable='dock_planner', name='dock_planner',
             parameters=[{'dock_x': number('dock_x'), 'dock_y': number('dock_y'),  # R6
                          'frame_id': 'map'}]),
    ]
    # [END nodes]
    return LaunchDescription(arguments + nodes)
