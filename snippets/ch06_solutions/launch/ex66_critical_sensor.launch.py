"""Exercise 6.6.1: start the processor when the sensor is ready; stop everything when it dies."""
from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessIO
from launch.events import Shutdown
from launch_ros.actions import Node


def generate_launch_description():
    sensor = Node(package='my_robot_pkg', executable='sensor_publisher', output='screen')
    processor = Node(package='my_robot_pkg', executable='data_processor', output='screen')

    def start_processor_when_ready(event):
        # event.text is a chunk of the sensor's stderr (its log lines), as bytes
        if b'Publishing distance readings' in event.text:
            return [LogInfo(msg='The sensor is ready: starting the processor'), processor]
        return None

    return LaunchDescription([
        sensor,
        RegisterEventHandler(OnProcessIO(
            target_action=sensor,
            on_stderr=start_processor_when_ready,
        )),
        RegisterEventHandler(OnProcessExit(
            target_action=sensor,
            on_exit=[
                LogInfo(msg='The sensor is gone: shutting down'),
                EmitEvent(event=Shutdown(reason='the sensor died')),
            ],
        )),
    ])
