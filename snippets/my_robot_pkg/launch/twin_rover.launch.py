"""A rover in Python, the file whose XML twin Exercise 6.11 asks for.

    ros2 launch my_robot_pkg twin_rover.launch.py
    ros2 launch my_robot_pkg twin_rover.launch.py rover_name:=rover7 max_speed:=0.4
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    rover_name = LaunchConfiguration('rover_name')
    return LaunchDescription([
        DeclareLaunchArgument('rover_name', default_value='rover1',
                              description='Namespace of the rover'),
        DeclareLaunchArgument('max_speed', default_value='1.2',
                              description='Top speed of the controller in m/s'),
        GroupAction([
            PushROSNamespace(rover_name),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
                 parameters=[{'publish_rate': 5.0}],
                 remappings=[('distance', 'scan_range')]),
            Node(package='my_robot_pkg', executable='data_processor', output='screen',
                 remappings=[('distance', 'scan_range')]),
            Node(package='my_robot_pkg', executable='robot_controller', output='screen',
                 parameters=[{'robot_name': rover_name,
                              'max_linear_speed': LaunchConfiguration('max_speed')}]),
        ]),
    ])
