"""Start the processor a fixed time after the sensor, with TimerAction.

    ros2 launch my_robot_pkg events_timer.launch.py
"""
from launch import LaunchDescription
from launch.actions import TimerAction
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START nodes]
        Node(
            package='events_demo_pkg',
            executable='flaky_sensor',
            parameters=[{'warmup': 1.0}],
            output='screen',
        ),
        TimerAction(
            period=3.0,  # seconds after this action is reached
            actions=[
                Node(package='my_robot_pkg', executable='data_processor', output='screen'),
            ],
        ),
        # [END nodes]
    ])
