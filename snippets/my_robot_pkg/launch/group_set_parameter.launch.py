"""SetParameter: one parameter value for every node of a group.

    ros2 launch my_robot_pkg group_set_parameter.launch.py

In simulation every node of the robot must take its time from the
simulator's /clock topic: `use_sim_time`, a parameter every node has, set
once for the group.  The controller comes after the group and keeps the
default, False.
"""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace, SetParameter


def generate_launch_description():
    return LaunchDescription([
        # [START group]
        GroupAction([
            PushROSNamespace('robot1'),
            SetParameter(name='use_sim_time', value=True),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
            Node(package='my_robot_pkg', executable='data_processor', output='screen'),
        ]),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen'),
        # [END group]
    ])
