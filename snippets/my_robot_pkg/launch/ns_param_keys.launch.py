"""Common mistake: a parameter file keyed by the bare node name.

    ros2 launch my_robot_pkg ns_param_keys.launch.py

Two namespaced controllers.  robot1 gets ns_controller_bare.yaml, whose key
is "robot_controller"; robot2 gets ns_controller_any_ns.yaml, whose key is
"/**/robot_controller".  Only one of them gets its settings.
"""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    config = PathJoinSubstitution([FindPackageShare('my_robot_pkg'), 'config'])
    return LaunchDescription([
        # [START nodes]
        Node(package='my_robot_pkg', executable='robot_controller', namespace='robot1',
             parameters=[PathJoinSubstitution([config, 'ns_controller_bare.yaml'])],
             output='screen'),
        Node(package='my_robot_pkg', executable='robot_controller', namespace='robot2',
             parameters=[PathJoinSubstitution([config, 'ns_controller_any_ns.yaml'])],
             output='screen'),
        # [END nodes]
    ])
