"""Exercise 6.4.1: start the controller with ex64_fast_robot.yaml from this package."""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params_file = PathJoinSubstitution(
        [FindPackageShare('ch06_solutions'), 'config', 'ex64_fast_robot.yaml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
