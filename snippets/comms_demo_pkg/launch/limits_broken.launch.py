"""The speed-limit server and the speed governor that obeys it.

    ros2 launch comms_demo_pkg limits_broken.launch.py

The governor is no use without a limit, so it is started only once the
server has published one (its "Published speed limit" log line).
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
        output='screen',
    )
    governor = Node(
        package='comms_demo_pkg',
        executable='speed_governor',
        name='speed_governor',
        output='screen',
    )
    # [END nodes]

    # [START start_after]
    started = []

    def start_governor_once(event):
        """Start the governor at the server's first "Published speed limit" line."""
        if started or b'Published speed limit' not in event.text:
            return None
        started.append(governor)
        return [governor]

    return LaunchDescription([
        server,
        # Node log lines go to stderr (or stdout, depending on settings): watch both.
        RegisterEventHandler(OnProcessIO(
            target_action=server,
            on_stdout=start_governor_once,
            on_stderr=start_governor_once,
        )),
    ])
    # [END start_after]
