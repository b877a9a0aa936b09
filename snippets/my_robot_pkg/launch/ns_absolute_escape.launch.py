"""Common mistake: an absolute name in a remapping escapes the namespace.

    ros2 launch my_robot_pkg ns_absolute_escape.launch.py

Two robots as in ns_two_robots.launch.py, but the controller's input is
remapped to "/obstacle_distance".  A name that starts with / is absolute:
the namespace is not put in front of it, so both robots share one topic.
"""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace


def robot(namespace: str) -> GroupAction:
    """One robot whose filter output is renamed, with a leading slash."""
    # [START robot]
    return GroupAction([
        PushROSNamespace(namespace),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
        Node(package='my_robot_pkg', executable='data_processor', output='screen',
             remappings=[('distance_filtered', '/obstacle_distance')]),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             remappings=[('distance_filtered', '/obstacle_distance')]),
    ])
    # [END robot]


def generate_launch_description():
    return LaunchDescription([robot('robot1'), robot('robot2')])
