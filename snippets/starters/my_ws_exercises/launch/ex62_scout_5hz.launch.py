"""Exercise 6.2.3: scout with its control loop at 5 Hz.

Start the controller with my_robot_pkg's config/robot_params.yaml (scout)
and update_rate 5.0.  The controller reads update_rate once, when it
starts: the value must be there before it starts.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex62_scout_5hz.launch.py
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution  # noqa: F401  (you will need it)
from launch_ros.actions import Node  # noqa: F401
from launch_ros.substitutions import FindPackageShare  # noqa: F401


def generate_launch_description():
    return LaunchDescription([
        # TODO: robot_controller (my_robot_pkg), named robot_controller, with
        #       scout's robot_params.yaml and a control loop at 5 Hz
    ])
