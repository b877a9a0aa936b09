# Mistake: only the topic name is fixed; the filter still runs in ROS_DOMAIN_ID 101.
# Verdict names: another ROS_DOMAIN_ID
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher',
             name='sensor_publisher', output='screen'),
        Node(package='my_robot_pkg', executable='data_processor', name='data_processor',
             additional_env={'ROS_DOMAIN_ID': '101'}, output='screen'),
    ])
