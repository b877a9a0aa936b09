"""Exercise 6.2.1: the controller of "turtle", configured from a YAML file.

This launch file is ready: it loads config/ex62_turtle.yaml of this package.
Your work is in that YAML file.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex62_turtle.launch.py
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    turtle_params = PathJoinSubstitution(
        [FindPackageShare('my_ws_exercises'), 'config', 'ex62_turtle.yaml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',  # the first key of ex62_turtle.yaml
            output='screen',
            parameters=[turtle_params],
        ),
    ])
