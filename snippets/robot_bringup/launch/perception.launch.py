"""The perception subsystem: the filter, tuned by config/perception.yaml.

    ros2 launch robot_bringup perception.launch.py
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # [START subsystem]
    tuned = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'config',
                                  'perception.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value=tuned,
                              description="The filter's parameter file"),
        Node(package='my_robot_pkg', executable='data_processor', output='screen',
             parameters=[LaunchConfiguration('params_file')]),
    ])
    # [END subsystem]
