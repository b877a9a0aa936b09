"""Shut the whole launch down when a critical node dies.

    ros2 launch my_robot_pkg events_critical.launch.py
"""
from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessIO, OnShutdown
from launch.events import Shutdown
from launch_ros.actions import Node


def generate_launch_description():
    # [START nodes]
    sensor = Node(
        package='events_demo_pkg',
        executable='flaky_sensor',
        parameters=[{'warmup': 0.5, 'crash_after': 4}],  # dies after 4 readings
        output='screen',
    )
    processor = Node(package='my_robot_pkg', executable='data_processor', output='screen')
    # [END nodes]
    return LaunchDescription([
        sensor,
        processor,
        # [START handlers]
        RegisterEventHandler(OnProcessIO(
            target_action=sensor,
            # node log lines go to stderr; pick out the one that matters
            on_stderr=lambda event: LogInfo(msg='The sensor reported a hardware fault')
            if b'Lost contact' in event.text else None,
        )),
        RegisterEventHandler(OnProcessExit(
            target_action=sensor,
            on_exit=[
                LogInfo(msg='The sensor is gone: nothing works without it, shutting down'),
                EmitEvent(event=Shutdown(reason='the sensor died')),
            ],
        )),
        RegisterEventHandler(OnShutdown(
            on_shutdown=lambda event, context: LogInfo(
                msg=f'Launch is shutting down: {event.reason}'),
        )),
        # [END handlers]
    ])
