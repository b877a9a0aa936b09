"""The sensors subsystem: one range sensor.  Its only argument is its own.

    ros2 launch robot_bringup sensors.launch.py rate:=5.0
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # [START subsystem]
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='2.0',
                              description='Sensor readings per second (a decimal number)'),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=[{'publish_rate': LaunchConfiguration('rate')}]),
    ])
    # [END subsystem]
