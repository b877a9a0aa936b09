"""Parameters from several sources at once: which value does a node get?

    ros2 launch my_robot_pkg layered_params.launch.py

The controller gets the robot's file, then the slow-mode file, then one
inline value; for a parameter set more than once, the later entry wins.
The sensor gets only the slow-mode file.
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # [START files]
    robot_params = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'robot_params.yaml'])
    slow_mode = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'slow_mode.yaml'])
    # [END files]
    return LaunchDescription([
        # [START nodes]
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='sensor_publisher',
            output='screen',
            parameters=[slow_mode],
        ),
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            parameters=[
                robot_params,                 # 1. the robot's settings
                slow_mode,                    # 2. replaces max_linear_speed
                {'robot_name': 'scout_2'},    # 3. replaces robot_name
            ],
        ),
        # [END nodes]
    ])
