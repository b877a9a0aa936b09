"""Exercise 6.5.1: two namespaced sensors, one processor.

Start sensor_publisher of my_robot_pkg twice, in the namespaces front and
rear (nodes /front/sensor_publisher and /rear/sensor_publisher), and one
data_processor in no namespace that averages the readings of both sensors
from the topic /ranges.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex65_two_sensors.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node  # noqa: F401  (you will need it)


def generate_launch_description():
    return LaunchDescription([
        # TODO: sensor_publisher in the namespace front, publishing on /ranges
        # TODO: sensor_publisher in the namespace rear, publishing on /ranges
        # TODO: data_processor (no namespace), reading /ranges
    ])
