"""Two robots from one launch file: the same three nodes, once under /robot1
and once under /robot2.

    ros2 launch my_robot_pkg ns_two_robots.launch.py

Each GroupAction starts with PushROSNamespace, which puts every node of the
group (and none outside it) into that namespace.
"""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace


# [START robot]
def robot(namespace: str, robot_name: str) -> GroupAction:
    """One robot: sensor -> processor -> controller, all in `namespace`."""
    return GroupAction([
        PushROSNamespace(namespace),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
        Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             parameters=[{'robot_name': robot_name}]),
    ])
# [END robot]


def generate_launch_description():
    # [START robots]
    return LaunchDescription([
        robot('robot1', 'alpha'),
        robot('robot2', 'bravo'),
    ])
    # [END robots]
