"""The whole robot, each node configured with parameters written in the launch file.

    ros2 launch my_robot_pkg controller_params.launch.py

Each `parameters=[{...}]` entry is a Python dict: parameter name -> value.
The Python type of each value becomes the parameter's type (lesson 6.2).
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START sensor_and_processor]
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='sensor_publisher',
            output='screen',
            parameters=[{'publish_rate': 4.0}],   # float -> DOUBLE
        ),
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            output='screen',
            parameters=[{'window_size': 5}],      # int -> INTEGER
        ),
        # [END sensor_and_processor]
        # [START controller]
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            name='robot_controller',
            output='screen',
            parameters=[{
                'robot_name': 'rover',            # str -> STRING
                'update_rate': 5.0,               # float -> DOUBLE
                'max_linear_speed': 0.3,          # float -> DOUBLE
                'enabled_sensors': ['lidar'],     # list of str -> STRING_ARRAY
                'sensors.camera.enabled': True,   # bool -> BOOL (a nested name, with dots)
            }],
        ),
        # [END controller]
    ])
