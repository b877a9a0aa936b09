# Mistake: the default is the text 'config/ex64_slow_robot.yaml', a path relative to the
#   folder the terminal is in, not the installed file.
# Verdict names: is a relative path
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # The default is not a text but a substitution: the path of the
        # installed file, found when the launch runs.
        DeclareLaunchArgument(
            'params_file',
            default_value='config/ex64_slow_robot.yaml',
            description='Parameter file of the controller (a full path)',
        ),
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[LaunchConfiguration('params_file')],
            output='screen',
        ),
    ])
