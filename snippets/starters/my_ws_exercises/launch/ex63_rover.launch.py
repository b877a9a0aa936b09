"""Exercise 6.3.1: a rover with three knobs.

Declare three launch arguments and use them:
    robot_name  default 'rover', with a description
    max_speed   default '0.3', with a description
    use_sensor  default 'true', only 'true' or 'false' accepted

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex63_rover.launch.py --show-args
    ros2 launch my_ws_exercises ex63_rover.launch.py \
        robot_name:=explorer max_speed:=1.5 use_sensor:=false
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo  # noqa: F401  (you will need them)
from launch.conditions import IfCondition  # noqa: F401
from launch.substitutions import LaunchConfiguration, PythonExpression  # noqa: F401
from launch_ros.actions import Node  # noqa: F401


def generate_launch_description():
    return LaunchDescription([
        # TODO: DeclareLaunchArgument for robot_name, max_speed and use_sensor
        # TODO: robot_controller (my_robot_pkg), its parameters robot_name and
        #       max_linear_speed set from the arguments
        # TODO: sensor_publisher (my_robot_pkg), only when use_sensor is true
        # TODO: LogInfo 'Fast robot: max_speed ... m/s is above 1.0 m/s',
        #       only when max_speed is above 1.0
    ])
