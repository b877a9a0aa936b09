"""Exercise 6.9.1: the speed governor must get the speed limit.

    ros2 launch my_ws_exercises ex69_speed_limit.launch.py

A copy of comms_demo_pkg's limits_broken.launch.py. The server publishes the
limit once; the governor is started only after that (at the server's
"Published speed limit" line), and never receives it.

TODO: make the governor get the limit although it starts after the publish.
Keep the start order: the governor must still start after the server's
"Published speed limit" line. The nodes' code stays as it is.
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
        output='screen',
    )
    governor = Node(
        package='comms_demo_pkg',
        executable='speed_governor',
        name='speed_governor',
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
