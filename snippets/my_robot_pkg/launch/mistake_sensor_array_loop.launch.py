"""Mistake (lesson 6.11): a loop over a launch argument written straight
into generate_launch_description().  It runs before any argument has a
value, so LaunchConfiguration is still a description, not a number.

    ros2 launch my_robot_pkg mistake_sensor_array_loop.launch.py sensor_count:=5
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # [START loop]
    count = int(LaunchConfiguration('sensor_count'))  # no value yet: this fails
    sensors = [Node(package='my_robot_pkg', executable='sensor_publisher',
                    name=f'sensor_{number}') for number in range(1, count + 1)]
    # [END loop]
    return LaunchDescription([
        DeclareLaunchArgument('sensor_count', default_value='3'),
        *sensors,
    ])
