# Mistake: only the renamed sensor is started; nobody filters /distance.
# Verdict names: /data_processor is not in the graph
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            name='front_sensor',
            output='screen',
        ),
    ])
