"""The controller, configured from the parameter file config/robot_params.yaml.

    ros2 launch my_robot_pkg controller_yaml.launch.py
"""
# [START imports]
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
# [END imports]


def generate_launch_description():
    # [START params_file]
    # <install>/share/my_robot_pkg/config/robot_params.yaml, worked out when
    # the launch runs: the installed copy, not the one in src/.
    params_file = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'robot_params.yaml'])
    # [END params_file]
    return LaunchDescription([
        # [START node]
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',   # must match the first key in the YAML file
            output='screen',
            parameters=[params_file],
        ),
        # [END node]
    ])
