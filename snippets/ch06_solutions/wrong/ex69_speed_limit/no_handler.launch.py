# Mistake: the event handler is removed and both nodes start at once: the governor gets the
#   limit, but it no longer waits for one to exist (the order the task keeps).
# Verdict names: started before the server published
from launch import LaunchDescription
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

    return LaunchDescription([server, governor])
