# Mistake: the parameter file is given as a relative path, 'config/ex64_fast_robot.yaml':
#   it is looked up from the folder the terminal is in, not in the package.
# Verdict names: is a relative path
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params_file = 'config/ex64_fast_robot.yaml'
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
