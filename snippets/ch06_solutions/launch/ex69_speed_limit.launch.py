"""Exercise 6.9.1, solved: the governor gets the limit it starts too late for.

    ros2 launch my_ws_exercises ex69_speed_limit.launch.py

Both ends of speed_limit are transient_local: the server's publisher keeps
its last limit and hands it to a subscription that matches later, if that
subscription asks for it. The governor still starts after the publish.
"""
from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessIO
from launch_ros.actions import Node


def generate_launch_description():
    server = Node(
        package='comms_demo_pkg',
        executable='limit_server',
        name='limit_server',
        parameters=[{'durability': 'transient_local'}],
        output='screen',
    )
    governor = Node(
        package='comms_demo_pkg',
        executable='speed_governor',
        name='speed_governor',
        parameters=[{'durability': 'transient_local'}],
        output='screen',
    )

    started = []

    def start_governor_once(event):
        """Start the governor at the server's first "Published speed limit" line."""
        if started or b'Published speed limit' not in event.text:
            return None
        started.append(governor)
        return [governor]

    return LaunchDescription([
        server,
        RegisterEventHandler(OnProcessIO(
            target_action=server,
            on_stdout=start_governor_once,
            on_stderr=start_governor_once,
        )),
    ])
