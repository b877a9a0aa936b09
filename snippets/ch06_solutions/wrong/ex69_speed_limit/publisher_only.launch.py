# Mistake: only the server keeps its limit (transient_local); the governor's volatile
#   subscription does not ask for kept messages, so it still gets nothing.
# Verdict names: its subscription is volatile
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
