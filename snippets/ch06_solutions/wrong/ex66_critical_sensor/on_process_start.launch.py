# Mistake: OnProcessStart fires when the sensor's process exists, long before the node is ready.
# Verdict names: data_processor started before the sensor was ready
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.events import Shutdown
from launch_ros.actions import Node


def generate_launch_description():
    sensor = Node(package='my_robot_pkg', executable='sensor_publisher', output='screen')
    processor = Node(package='my_robot_pkg', executable='data_processor', output='screen')
    return LaunchDescription([
        sensor,
        RegisterEventHandler(OnProcessStart(target_action=sensor, on_start=[processor])),
        RegisterEventHandler(OnProcessExit(
            target_action=sensor,
            on_exit=[EmitEvent(event=Shutdown(reason='the sensor died'))],
        )),
    ])
