"""Exercise 6.4.1: ship a second configuration.

Start robot_controller (package my_robot_pkg) with the parameter file
config/ex64_fast_robot.yaml of this package, as colcon build installed it.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex64_fast_robot.launch.py
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution  # noqa: F401  (you will need them)
from launch_ros.actions import Node  # noqa: F401
from launch_ros.substitutions import FindPackageShare  # noqa: F401


def generate_launch_description():
    return LaunchDescription([
        # TODO: robot_controller with parameters=[the installed
        #       config/ex64_fast_robot.yaml of my_ws_exercises]
    ])
