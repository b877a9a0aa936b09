"""Lesson 6.8: the short version of the patrol launch file that trusts the file.

    ros2 launch my_robot_pkg patrol_file_unchanged.launch.py

config/robot_params.yaml is passed as it is, with robot_name set after it.
The file keys its section `robot_controller:`, which means /robot_controller,
so the controller in /scout takes nothing from it: the running check shows
the code's defaults.  Kept to show why the assistant's draft rewrote the file.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot_name = LaunchConfiguration('robot_name')
    sensor_rate = LaunchConfiguration('sensor_rate')
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='scout',
                              description="Namespace of every node and the controller's name"),
        DeclareLaunchArgument('sensor_rate', default_value='5.0',
                              description='Sensor rate in Hz'),
        Node(package='my_robot_pkg', executable='sensor_publisher', name='sensor_publisher',
             namespace=robot_name,
             parameters=[{'publish_rate': ParameterValue(sensor_rate, value_type=float)}]),
        Node(package='my_robot_pkg', executable='data_processor', name='data_processor',
             namespace=robot_name,
             parameters=[{'window_size': 5}]),
        # [START controller]
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             namespace=robot_name,
             parameters=[
                 PathJoinSubstitution(
                     [FindPackageShare('my_robot_pkg'), 'config', 'robot_params.yaml']),
                 {'robot_name': ParameterValue(robot_name, value_type=str)},
             ]),
        # [END controller]
    ])
