"""Name the robot on the command line; any name stays a string.

    ros2 launch my_robot_pkg robot_name_arg.launch.py robot_name:=042

The fixed version of mistake_robot_name_arg.launch.py (lesson 6.2):
ParameterValue(..., value_type=str) keeps the text as it was typed.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
# [START import]
from launch_ros.parameter_descriptions import ParameterValue
# [END import]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='my_robot'),
        # [START node]
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            parameters=[{
                'robot_name': ParameterValue(LaunchConfiguration('robot_name'),
                                             value_type=str),
            }],
        ),
        # [END node]
    ])
