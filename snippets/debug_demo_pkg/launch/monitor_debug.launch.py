"""The repaired system with the monitor's own log level set to debug.

    ros2 launch debug_demo_pkg monitor_debug.launch.py

`ros_arguments` adds `--ros-args --log-level obstacle_monitor:=debug` to
the monitor's command line: its debug lines appear, the sensors' do not.
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # [START monitor]
        Node(
            package='debug_demo_pkg',
            executable='obstacle_monitor',
            name='obstacle_monitor',
            parameters=[{'sensors': ['front', 'rear']}],
            ros_arguments=['--log-level', 'obstacle_monitor:=debug'],
            output='screen',
        ),
        # [END monitor]
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',
            name='front_sensor',
            remappings=[('range', 'range/front')],
            output='screen',
        ),
        Node(
            package='debug_demo_pkg',
            executable='range_sensor',
            name='rear_sensor',
            remappings=[('range', 'range/rear')],
            output='screen',
        ),
    ])
