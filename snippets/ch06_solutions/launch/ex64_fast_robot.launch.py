"""Exercise 6.4.1: start the controller with ex64_fast_robot.yaml of this package.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex64_fast_robot.launch.py
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # The installed copy: install/my_ws_exercises/share/my_ws_exercises/config/...
    params_file = PathJoinSubstitution(
        [FindPackageShare('my_ws_exercises'), 'config', 'ex64_fast_robot.yaml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
