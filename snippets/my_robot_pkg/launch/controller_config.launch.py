"""Start the controller with the parameter file installed with this package.

FindPackageShare finds the package's share folder when the launch runs.
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # [START params_file]
    params_file = PathJoinSubstitution([
        FindPackageShare('my_robot_pkg'),  # .../install/my_robot_pkg/share/my_robot_pkg
        'config',
        'robot_params.yaml',
    ])
    # [END params_file]
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
