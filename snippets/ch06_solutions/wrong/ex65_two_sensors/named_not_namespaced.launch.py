# Mistake: the sensors are renamed (name='front') instead of namespaced: nodes /front, /rear.
# Verdict names: /front/sensor_publisher is not in the graph
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher', name='front',
             remappings=[('distance', '/ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='sensor_publisher', name='rear',
             remappings=[('distance', '/ranges')], output='screen'),
        Node(package='my_robot_pkg', executable='data_processor',
             remappings=[('distance', '/ranges')], output='screen'),
    ])
