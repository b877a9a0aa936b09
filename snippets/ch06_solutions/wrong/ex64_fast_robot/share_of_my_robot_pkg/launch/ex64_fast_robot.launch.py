# Mistake: FindPackageShare names my_robot_pkg, the package of the node, but the file
#   is installed with my_ws_exercises.
# Verdict names: FindPackageShare must name the package the file is installed with
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # The installed copy: install/my_ws_exercises/share/my_ws_exercises/config/...
    params_file = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'ex64_fast_robot.yaml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
