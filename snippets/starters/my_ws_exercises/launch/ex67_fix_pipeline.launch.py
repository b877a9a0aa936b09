"""Exercise 6.7.1: make the data flow.

This launch file starts the sensor and the filter of my_robot_pkg.  Both
start and neither crashes, yet the filter never receives a reading and
nothing comes out on /distance_filtered.  Find out why with the tools of
lesson 6.7, then fix this file so that the readings flow
/sensor_publisher -> /distance -> /data_processor -> /distance_filtered.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex67_fix_pipeline.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # TODO: find what keeps the readings from arriving, and fix it.
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='sensor_publisher',
            remappings=[('distance', 'distance_raw')],
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            additional_env={'ROS_DOMAIN_ID': '101'},
            output='screen',
        ),
    ])
