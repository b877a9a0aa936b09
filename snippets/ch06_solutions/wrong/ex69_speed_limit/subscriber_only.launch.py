# Mistake: only the governor asks for transient_local; the server's publisher stays volatile,
#   an incompatible pair: they never connect, and even a new publish does not arrive.
# Verdict names: offering incompatible QoS
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
