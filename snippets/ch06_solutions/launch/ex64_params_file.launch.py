"""Exercise 6.4.2: which parameter file the controller gets is a launch argument.

    ros2 launch my_ws_exercises ex64_params_file.launch.py
    ros2 launch my_ws_exercises ex64_params_file.launch.py params_file:=/path/to/other.yaml
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        # The default is not a text but a substitution: the path of the
        # installed file, found when the launch runs.
        DeclareLaunchArgument(
            'params_file',
            default_value=PathJoinSubstitution(
                [FindPackageShare('my_ws_exercises'), 'config', 'ex64_slow_robot.yaml']),
            description='Parameter file of the controller (a full path)',
        ),
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[LaunchConfiguration('params_file')],
            output='screen',
        ),
    ])
