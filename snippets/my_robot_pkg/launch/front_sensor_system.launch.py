"""Lesson 6.8, exercise: the front sensor and its filter, as the requirements say.

    ros2 launch my_robot_pkg front_sensor_system.launch.py [rate:=10.0]

/front/sensor_publisher publishes /front/distance at `rate` Hz;
/front/data_processor averages the last 4 readings onto /front/distance_filtered.
A spec written from the requirements must pass this file and fail the two
front_sensor_system_bad_*.launch.py files, which each get one value wrong.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    rate = LaunchConfiguration('rate')
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='10.0', description='Sensor rate in Hz'),
        Node(package='my_robot_pkg', executable='sensor_publisher', name='sensor_publisher',
             namespace='front',
             parameters=[{'publish_rate': ParameterValue(rate, value_type=float)}]),
        Node(package='my_robot_pkg', executable='data_processor', name='data_processor',
             namespace='front', parameters=[{'window_size': 4}]),
    ])
