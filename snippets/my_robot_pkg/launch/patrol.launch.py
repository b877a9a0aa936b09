"""Lesson 6.8: the patrol robot, the assistant's draft after review.

    ros2 launch my_robot_pkg patrol.launch.py
    ros2 launch my_robot_pkg patrol.launch.py robot_name:=rover sensor_rate:=10.0

Every node runs in the namespace robot_name.  config/robot_params.yaml keys
the controller's settings `robot_controller:` (that is /robot_controller), so
given to /scout/robot_controller as a file it would be ignored.  The launch
file reads that section once and passes it as a dictionary: launch_ros gives
a dictionary to the node whatever its namespace, and removes the temporary
file it writes for it when the launch ends.
"""
import os

import yaml
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    # [START settings]
    params_file = os.path.join(
        get_package_share_directory('my_robot_pkg'), 'config', 'robot_params.yaml')
    with open(params_file) as stream:
        controller_settings = yaml.safe_load(stream)['robot_controller']['ros__parameters']
    # [END settings]
    robot_name = LaunchConfiguration('robot_name')
    sensor_rate = LaunchConfiguration('sensor_rate')
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='scout',
                              description="Namespace of every node and the controller's name"),
        DeclareLaunchArgument('sensor_rate', default_value='5.0',
                              description='Sensor rate in Hz'),
        # [START nodes]
        Node(package='my_robot_pkg', executable='sensor_publisher', name='sensor_publisher',
             namespace=robot_name,
             parameters=[{'publish_rate': ParameterValue(sensor_rate, value_type=float)}]),
        Node(package='my_robot_pkg', executable='data_processor', name='data_processor',
             namespace=robot_name,
             parameters=[{'window_size': 5}]),
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             namespace=robot_name,
             parameters=[
                 controller_settings,  # the file's section, as a dictionary
                 {'robot_name': ParameterValue(robot_name, value_type=str)},
             ]),
        # [END nodes]
    ])
