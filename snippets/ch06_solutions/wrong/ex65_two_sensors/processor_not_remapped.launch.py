# Mistake: only the sensors are remapped; the processor still reads its own topic name, /distance.
# Verdict names: /data_processor reads /distance instead of /ranges
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher', namespace='front',
             remappings=[('distance', '/ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', namespace='rear',
             remappings=[('distance', '/ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
    ])
