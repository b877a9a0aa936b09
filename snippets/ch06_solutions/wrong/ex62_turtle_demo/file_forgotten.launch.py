# Mistake: only the new speed is given; the turtle file is not loaded, so the rest are defaults
# Verdict names: got robot_name 'my_robot' (a string), expected 'turtle'
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             output='screen', parameters=[{'max_linear_speed': 0.35}]),
    ])
