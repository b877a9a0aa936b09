"""Start the processor when the sensor's process has started, with OnProcessStart.

    ros2 launch my_robot_pkg events_on_start.launch.py
"""
from launch import LaunchDescription
from launch.actions import LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    # [START nodes]
    sensor = Node(
        package='events_demo_pkg',
        executable='flaky_sensor',
        parameters=[{'warmup': 2.0}],
        output='screen',
    )
    processor = Node(package='my_robot_pkg', executable='data_processor', output='screen')
    return LaunchDescription([
        sensor,
        RegisterEventHandler(OnProcessStart(
            target_action=sensor,   # the action object, not a name
            on_start=[
                LogInfo(msg='The sensor process has started: starting the processor'),
                processor,
            ],
        )),
    ])
    # [END nodes]
