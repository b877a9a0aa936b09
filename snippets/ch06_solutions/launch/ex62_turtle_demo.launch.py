"""Exercise 6.2.2: "turtle" from its YAML file, one value changed for a demo.

    ros2 launch my_ws_exercises ex62_turtle_demo.launch.py
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    turtle_params = PathJoinSubstitution(
        [FindPackageShare('my_ws_exercises'), 'config', 'ex62_turtle.yaml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            parameters=[
                turtle_params,                  # everything from the file...
                {'max_linear_speed': 0.35},     # ...then this one value replaced
            ],
        ),
    ])
