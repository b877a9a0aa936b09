# Mistake: only the domain is fixed; the sensor still publishes on /distance_raw.
# Verdict names: /distance should go from /sensor_publisher to /data_processor
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher', name='sensor_publisher',
             remappings=[('distance', 'distance_raw')], output='screen'),
        Node(package='my_robot_pkg', executable='data_processor',
             name='data_processor', output='screen'),
    ])
