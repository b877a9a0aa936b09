# Mistake: the sensor is moved into ROS_DOMAIN_ID 101 as well: the two nodes see each other,
#   but nothing else on the robot (nor ros2 node list) sees either.
# Verdict names: another ROS_DOMAIN_ID
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher', name='sensor_publisher',
             additional_env={'ROS_DOMAIN_ID': '101'}, output='screen'),
        Node(package='my_robot_pkg', executable='data_processor', name='data_processor',
             additional_env={'ROS_DOMAIN_ID': '101'}, output='screen'),
    ])
