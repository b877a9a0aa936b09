"""Lesson 6.8, exercise: a planted defect - the rate argument defaults to 1.0 Hz.

    ros2 launch my_robot_pkg front_sensor_system_bad_rate.launch.py [rate:=1.0]

front_sensor_system.launch.py with one value wrong: the argument rate defaults
to 1.0 where the requirements say 10.0, so the sensor publishes at 1 Hz.
Everything starts and runs; a spec written from the requirements of exercise
6.8.1 must fail this file.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    rate = LaunchConfiguration('rate')
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='1.0', description='Sensor rate in Hz'),
        Node(package='my_robot_pkg', executable='sensor_publisher', name='sensor_publisher',
             namespace='front',
             parameters=[{'publish_rate': ParameterValue(rate, value_type=float)}]),
        Node(package='my_robot_pkg', executable='data_processor', name='data_processor',
             namespace='front', parameters=[{'window_size': 4}]),
    ])
