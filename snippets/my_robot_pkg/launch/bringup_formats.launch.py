"""One robot, in Python: the same bringup as bringup_formats.launch.xml and
bringup_formats.launch.yaml (lesson 6.11 compares the three).

    ros2 launch my_robot_pkg bringup_formats.launch.py --show-args
    ros2 launch my_robot_pkg bringup_formats.launch.py robot_name:=robot2 sensor_rate:=5.0
"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    # [START arguments]
    arguments = [
        DeclareLaunchArgument('robot_name', default_value='robot1',
                              description="Namespace of the robot and its controller's name"),
        DeclareLaunchArgument('sensor_rate', default_value='2.0',
                              description='Readings per second (a decimal number)'),
        DeclareLaunchArgument('use_controller', default_value='true',
                              choices=['true', 'false'],
                              description='Start robot_controller'),
    ]
    # [END arguments]
    robot_name = LaunchConfiguration('robot_name')
    params_file = os.path.join(get_package_share_directory('my_robot_pkg'),
                               'config', 'bringup_formats.yaml')

    # [START robot]
    robot = GroupAction([
        PushROSNamespace(robot_name),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=[{'publish_rate': LaunchConfiguration('sensor_rate')}],
             remappings=[('distance', 'range')]),
        Node(package='my_robot_pkg', executable='data_processor', output='screen',
             parameters=[params_file],
             remappings=[('distance', 'range')]),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             parameters=[params_file, {'robot_name': robot_name}],
             condition=IfCondition(LaunchConfiguration('use_controller'))),
    ])
    # [END robot]
    return LaunchDescription([*arguments, robot])
