# Mistake: the file's top-level key is controller, not the node's name robot_controller,
#   so no parameter of the file reaches the node.
# Verdict names: got robot_name 'my_robot', expected 'speedy'
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params_file = PathJoinSubstitution(
        [FindPackageShare('my_ws_exercises'), 'config', 'ex64_fast_robot.yaml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
