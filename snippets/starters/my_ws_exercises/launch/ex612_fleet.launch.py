"""Exercise 6.12.1: a fleet of scouts, as many as the argument robot_count asks for.

Start robot_count scouts (default 2), named scout1, scout2, ...  Each scout is
robot_bringup's launch/robot.launch.py, included with its robot_name (its
namespace) and with sensor_rate 5.0: scouts have fast sensors.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex612_fleet.launch.py
    ros2 launch my_ws_exercises ex612_fleet.launch.py robot_count:=3
"""
from launch import LaunchContext, LaunchDescription  # noqa: F401  (you will need these)
from launch.actions import DeclareLaunchArgument, GroupAction  # noqa: F401
from launch.actions import IncludeLaunchDescription, OpaqueFunction  # noqa: F401
from launch.launch_description_sources import PythonLaunchDescriptionSource  # noqa: F401
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution  # noqa: F401
from launch_ros.substitutions import FindPackageShare  # noqa: F401


def generate_launch_description():
    return LaunchDescription([
        # TODO: declare robot_count (default '2')
        # TODO: one scout per count: robot_bringup's robot.launch.py with
        #       robot_name scout1, scout2, ... and sensor_rate 5.0, each in its own group
    ])
