"""A launch file with a hidden mistake: a name from the command line used as is.

    ros2 launch my_robot_pkg mistake_robot_name_arg.launch.py robot_name:=rover
    ros2 launch my_robot_pkg mistake_robot_name_arg.launch.py robot_name:=042

Text given as `robot_name:=...` is read the way YAML reads a value, so
`042` becomes the integer 34 and the controller, which wants a string,
stops.  robot_name_arg.launch.py is the fixed version (lesson 6.2).
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START argument]
        DeclareLaunchArgument('robot_name', default_value='my_robot'),
        # [END argument]
        # [START node]
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            # MISTAKE: the text's type is guessed; `042` becomes the integer 34
            parameters=[{'robot_name': LaunchConfiguration('robot_name')}],
        ),
        # [END node]
    ])
