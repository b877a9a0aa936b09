"""Exercise 6.2.2: demo day.

Start the controller with config/ex62_turtle.yaml of this package, unchanged,
and max_linear_speed 0.35 instead of the file's value, without a second
YAML file.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex62_turtle_demo.launch.py
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution  # noqa: F401  (you will need it)
from launch_ros.actions import Node  # noqa: F401
from launch_ros.substitutions import FindPackageShare  # noqa: F401


def generate_launch_description():
    return LaunchDescription([
        # TODO: robot_controller (my_robot_pkg), named robot_controller, with
        #       everything from ex62_turtle.yaml and max_linear_speed 0.35
    ])
