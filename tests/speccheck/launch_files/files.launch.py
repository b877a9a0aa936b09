"""Test launch file: parameters from files (scoped SetParametersFromFile, a Node's own
file with namespaced and wildcard keys, a Parameter), SetUseSimTime and ros_arguments."""
import os

from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace, SetParametersFromFile, SetUseSimTime
from launch_ros.parameter_descriptions import Parameter

PARAMS = os.path.join(os.path.dirname(__file__), 'params.yaml')


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot1'),
            SetParametersFromFile(PARAMS),
            SetUseSimTime(True),
            Node(package='my_robot_pkg', executable='sensor_publisher', name='lidar'),
            Node(package='my_robot_pkg', executable='data_processor', name='filter',
                 ros_arguments=['-p', 'window_size:=9', '-r', 'distance:=/robot1/scan']),
        ]),
        Node(package='my_robot_pkg', executable='robot_controller', name='controller',
             namespace='robot2',
             parameters=[PARAMS, Parameter('enabled_sensors', ['lidar'])]),
    ])
