"""Exercise 6.12.1: robot_count scouts, each robot_bringup's robot.launch.py.

The count is known only when the launch runs, so the loop is in an
OpaqueFunction; each include gets every argument it needs and a group of its own.
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.actions import OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def scouts(context: LaunchContext) -> list[GroupAction]:
    count = int(LaunchConfiguration('robot_count').perform(context))
    robot = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                  'robot.launch.py'])
    return [GroupAction([IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot),
                launch_arguments={'robot_name': f'scout{number}',
                                  'sensor_rate': '5.0'}.items())])
            for number in range(1, count + 1)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='2',
                              description='How many scouts to start'),
        OpaqueFunction(function=scouts),
    ])
