"""Planted defect (lesson 6.15): dock_watch_v2.launch.py with the monitor remapped.

battery_monitor listens on /battery (a typo for battery_state), so it never hears
the battery: nothing is published on /battery_low and the planner never reports.
Every node still starts and ends cleanly.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    # [START arguments]
    arguments = [  # R7 and R8: the launch interface
        DeclareLaunchArgument('battery_rate', default_value='5.0',  # R2: was 2.0
                              description='Battery states per second (Hz)'),
        DeclareLaunchArgument('dock_x', default_value='0.0', description='Dock x in map (m)'),
        DeclareLaunchArgument('dock_y', default_value='0.0', description='Dock y in map (m)'),
        DeclareLaunchArgument('low_threshold', default_value='0.25',  # R8: new
                              description='Charge (0.05 to 0.95) at or below which the '
                                          'battery is low'),
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
             parameters=[{'low_threshold': number('low_threshold')}],  # R8
             remappings=[('battery_state', 'battery')]),  # the planted defect
        Node(package='dock_watch_pkg', executable='dock_planner', name='dock_planner',
             parameters=[{'dock_x': number('dock_x'), 'dock_y': number('dock_y'),  # R6
                          'frame_id': 'map'}]),
    ]
    # [END nodes]
    return LaunchDescription(arguments + nodes)
