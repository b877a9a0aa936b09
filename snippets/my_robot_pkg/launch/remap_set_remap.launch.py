"""SetRemap: one remapping for every node of a group.

    ros2 launch my_robot_pkg remap_set_remap.launch.py

Inside the group, sensor and processor both use /robot1/ranges instead of
/robot1/distance.  The controller comes after the group, so neither the
remapping nor the namespace applies to it.
"""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace, SetRemap


def generate_launch_description():
    return LaunchDescription([
        # [START group]
        GroupAction([
            PushROSNamespace('robot1'),
            SetRemap(src='distance', dst='ranges'),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
            Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        ]),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen'),
        # [END group]
    ])
