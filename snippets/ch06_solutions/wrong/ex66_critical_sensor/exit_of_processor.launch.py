# Mistake: the shutdown handler watches the processor's exit, not the sensor's.
# Verdict names: the launch kept running after the sensor died
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessIO
from launch.events import Shutdown
from launch_ros.actions import Node


def generate_launch_description():
    sensor = Node(package='my_robot_pkg', executable='sensor_publisher', output='screen')
    processor = Node(package='my_robot_pkg', executable='data_processor', output='screen')
    return LaunchDescription([
        sensor,
        RegisterEventHandler(OnProcessIO(
            target_action=sensor,
            on_stderr=lambda event: processor
            if b'Publishing distance readings' in event.text else None,
        )),
        RegisterEventHandler(OnProcessExit(
            target_action=processor,
            on_exit=[EmitEvent(event=Shutdown(reason='the sensor died'))],
        )),
    ])
