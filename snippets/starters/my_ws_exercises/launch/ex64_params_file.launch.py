"""Exercise 6.4.2: the parameter file as a launch argument.

Declare an argument params_file whose default is the installed
config/ex64_slow_robot.yaml of this package, and start robot_controller
(package my_robot_pkg) with the file the argument names.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex64_params_file.launch.py --show-args
    ros2 launch my_ws_exercises ex64_params_file.launch.py params_file:=/path/to/other.yaml
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument  # noqa: F401  (you will need them)
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution  # noqa: F401
from launch_ros.actions import Node  # noqa: F401
from launch_ros.substitutions import FindPackageShare  # noqa: F401


def generate_launch_description():
    return LaunchDescription([
        # TODO: DeclareLaunchArgument params_file, with a description; its
        #       default_value the installed config/ex64_slow_robot.yaml
        # TODO: robot_controller with parameters=[the file params_file names]
    ])
