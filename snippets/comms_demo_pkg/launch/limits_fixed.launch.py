"""limits_broken.launch.py repaired: the governor gets the limit it joined too late for.

    ros2 launch comms_demo_pkg limits_fixed.launch.py

The server still publishes the limit once, before the governor exists.  With
durability 'transient_local' on both sides, the server's publisher keeps the
last limit (depth 1) and hands it to the governor when the governor's
subscription matches; a volatile subscriber would still get nothing, so
both must change.
"""
from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessIO
from launch_ros.actions import Node


def generate_launch_description():
    # [START nodes]
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
    # [END nodes]

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
