"""The control subsystem: the controller, tuned by config/control.yaml.

    ros2 launch robot_bringup control.launch.py robot_name:=robot1
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # [START subsystem]
    tuned = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'config', 'control.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='robot',
                              description="The controller's robot_name parameter"),
        DeclareLaunchArgument('rate', default_value='20.0',
                              description='Control loop updates per second (a decimal number)'),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             parameters=[tuned, {'robot_name': LaunchConfiguration('robot_name'),
                                 'update_rate': LaunchConfiguration('rate')}]),
    ])
    # [END subsystem]
