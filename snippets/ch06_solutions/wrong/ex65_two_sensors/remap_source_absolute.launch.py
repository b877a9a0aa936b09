# Mistake: the remap names '/distance'; the sensor's topic is /front/distance: it matches nothing.
# Verdict names: /front/sensor_publisher publishes /front/distance instead of /ranges
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher', namespace='front',
             remappings=[('/distance', '/ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', namespace='rear',
             remappings=[('/distance', '/ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='data_processor',
             remappings=[('distance', '/ranges')], output='screen'),
    ])
