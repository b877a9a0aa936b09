# Mistake: 'transient-local' with a hyphen: the server refuses the value and dies at start,
#   so the governor is never started.
# Verdict names: ValueError: parameter 'durability' is 'transient-local'
from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessIO
from launch_ros.actions import Node


def generate_launch_description():
    server = Node(
        package='comms_demo_pkg',
        executable='limit_server',
        name='limit_server',
        parameters=[{'durability': 'transient-local'}],
        output='screen',
    )
    governor = Node(
        package='comms_demo_pkg',
        executable='speed_governor',
        name='speed_governor',
        parameters=[{'durability': 'transient-local'}],
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
