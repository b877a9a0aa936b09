"""A launch file with a common mistake: an integer where the node expects a float.

    ros2 launch my_robot_pkg mistake_integer_rate.launch.py

robot_controller declares update_rate with the default 10.0, a float, so
the parameter's type is DOUBLE.  `2` is an int, so the node refuses it and
stops.  Lesson 6.2 shows what happens and the fix: write `2.0`.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START node]
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            parameters=[{'update_rate': 2}],   # MISTAKE: 2 is an int; write 2.0
        ),
        # [END node]
    ])
