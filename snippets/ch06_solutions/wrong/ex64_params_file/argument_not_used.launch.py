# Mistake: params_file is declared, but the Node is given the default path itself, so
#   params_file:=... on the command line changes nothing.
# Verdict names: expected 'from_the_command_line' from params_file:=
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument(
            'params_file',
            default_value=PathJoinSubstitution(
                [FindPackageShare('my_ws_exercises'), 'config', 'ex64_slow_robot.yaml']),
            description='Parameter file of the controller (a full path)',
        ),
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[PathJoinSubstitution(
                [FindPackageShare('my_ws_exercises'), 'config', 'ex64_slow_robot.yaml'])],
            output='screen',
        ),
    ])
