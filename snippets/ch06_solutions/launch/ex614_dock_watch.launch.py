"""Exercise 6.14.1: the dock watch system, version 3 (one robot in its namespace).

    ros2 launch my_ws_exercises ex614_dock_watch.launch.py
    ros2 launch my_ws_exercises ex614_dock_watch.launch.py robot:=rover

Meets dock_watch_pkg's specs/dock_watch_robot.spec.yaml: version 2 plus R9,
every node in the namespace named by the argument robot.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace
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
        # [START robot]
        DeclareLaunchArgument('robot', default_value='scout',  # R9
                              description='Name of the robot: the namespace of every node'),
        # [END robot]
    ]

    def number(argument: str) -> ParameterValue:
        """A launch argument as a double, so `battery_rate:=5` is 5.0, not the integer 5."""
        return ParameterValue(LaunchConfiguration(argument), value_type=float)

    nodes = [
        Node(package='dock_watch_pkg', executable='battery_sim', name='battery_sim',
             parameters=[{'publish_rate': number('battery_rate')}]),
        Node(package='dock_watch_pkg', executable='battery_monitor', name='battery_monitor',
             parameters=[{'low_threshold': number('low_threshold')}]),
        Node(package='dock_watch_pkg', executable='dock_planner', name='dock_planner',
             parameters=[{'dock_x': number('dock_x'), 'dock_y': number('dock_y'),
                          'frame_id': 'map'}]),
    ]
    # [START namespace]
    # R9: one namespace for the whole group, so a node added later cannot miss it
    robot = GroupAction([PushROSNamespace(LaunchConfiguration('robot')), *nodes])
    # [END namespace]
    return LaunchDescription(arguments + [robot])
