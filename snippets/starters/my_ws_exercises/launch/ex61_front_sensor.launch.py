"""Exercise 6.1.2: the same program under another name.

Start the program sensor_publisher of my_robot_pkg as a node called
front_sensor, together with data_processor.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex61_front_sensor.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node  # noqa: F401  (you will need it)


def generate_launch_description():
    return LaunchDescription([
        # TODO: sensor_publisher, running as the node front_sensor
        # TODO: data_processor
    ])
