"""A planted defect for exercise 7.1.1: the capstone with three robots, where
turtle3 runs with turtle4's configuration (its route along the bottom edge,
stop_distance 1.0) instead of its own.

Every node and topic of R9 is there, wired as in the real capstone; only
parameter values differ, so a spec that names nodes and topics but no values
passes it.  Composed from capstone_bringup's own subsystem files.
"""
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare

BRINGUP = FindPackageShare('capstone_bringup')


def include(name: str, **arguments: str) -> GroupAction:
    source = PythonLaunchDescriptionSource(PathJoinSubstitution([BRINGUP, 'launch', name]))
    return GroupAction(scoped=True, actions=[
        IncludeLaunchDescription(source, launch_arguments=arguments.items())])


def generate_launch_description():
    return LaunchDescription([
        include('sim.launch.py', robot_count='3'),
        include('robot.launch.py', robot='turtle1'),
        include('robot.launch.py', robot='turtle2'),
        # The defect: turtle3's nodes read turtle4's file.
        include('robot.launch.py', robot='turtle3',
                robot_params=PathJoinSubstitution([BRINGUP, 'config', 'turtle4.yaml'])),
    ])
