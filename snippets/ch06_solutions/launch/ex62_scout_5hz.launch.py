"""Exercise 6.2.3: scout from robot_params.yaml, its control loop started at 5 Hz.

    ros2 launch my_ws_exercises ex62_scout_5hz.launch.py
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    scout_params = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'robot_params.yaml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            parameters=[
                scout_params,             # scout's settings, update_rate 20.0 among them
                {'update_rate': 5.0},     # later entry wins; read when the node starts
            ],
        ),
    ])
