"""One robot: its controller in its own namespace.  Meant to be included,
once per robot, by a bringup launch file such as bringup_twice.launch.py."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    robot_ns = LaunchConfiguration('robot_ns')
    robot_name = LaunchConfiguration('robot_name')
    return LaunchDescription([
        # [START arguments]
        # No default_value: whoever starts this file must give robot_ns.
        DeclareLaunchArgument('robot_ns', description='Namespace of this robot, e.g. robot1'),
        DeclareLaunchArgument('robot_name', default_value='scout',
                              description='Name the controller reports'),
        # [END arguments]
        LogInfo(msg=['Starting controller of ', robot_name, ' in namespace /', robot_ns]),
        # [START node]
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            namespace=robot_ns,  # robot1 -> the node is /robot1/robot_controller
            parameters=[{'robot_name': robot_name}],
            output='screen',
        ),
        # [END node]
    ])
