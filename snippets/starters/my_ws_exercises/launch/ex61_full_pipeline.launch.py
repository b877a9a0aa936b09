"""Exercise 6.1.1: the whole robot from one launch file.

Start the three nodes of my_robot_pkg so that the data flows
sensor_publisher -> /distance -> data_processor -> /distance_filtered
-> robot_controller -> /cmd_vel.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex61_full_pipeline.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node  # noqa: F401  (you will need it)


def generate_launch_description():
    return LaunchDescription([
        # TODO: one Node action for sensor_publisher
        # TODO: one Node action for data_processor
        # TODO: one Node action for robot_controller
    ])
