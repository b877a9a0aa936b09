"""Exercise 6.5.2: two robots from one launch file, configured by one file.

Start two robots, robot1 and robot2, each with sensor_publisher,
data_processor and robot_controller of my_robot_pkg in its own namespace,
so that each robot's readings stay inside that robot.  Both controllers take
their settings from config/ex65_robots.yaml of this package.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex65_two_robots.launch.py
"""
from launch import LaunchDescription
from launch.actions import GroupAction  # noqa: F401  (you will need these)
from launch.substitutions import PathJoinSubstitution  # noqa: F401
from launch_ros.actions import Node, PushROSNamespace  # noqa: F401
from launch_ros.substitutions import FindPackageShare  # noqa: F401


def generate_launch_description():
    return LaunchDescription([
        # TODO: robot1: its three nodes in the namespace robot1; the controller
        #       gets config/ex65_robots.yaml of my_ws_exercises as its parameters
        # TODO: robot2: the same in the namespace robot2
    ])
