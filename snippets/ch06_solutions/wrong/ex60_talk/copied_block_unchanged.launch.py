# Mistake: the processor's line copied for terminal 2 and the executable left unchanged
# Verdict names: 2 processes run as the node /data_processor
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
    ])
