"""Exercise 6.7.1: the sensor and the filter, with both faults fixed.

    ros2 launch ch06_solutions ex67_fix_pipeline.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='sensor_publisher',
            # no remapping: the sensor publishes on /distance, where the filter listens
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            # no additional_env: the filter joins the launch's own ROS_DOMAIN_ID
            output='screen',
        ),
    ])
