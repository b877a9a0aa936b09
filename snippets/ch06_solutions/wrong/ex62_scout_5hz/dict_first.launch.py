# Mistake: the dictionary comes before robot_params.yaml, so the file's 20.0 wins
# Verdict names: got update_rate 20.0 (a float), expected 5.0
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    scout_params = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'robot_params.yaml'])
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             output='screen', parameters=[{'update_rate': 5.0}, scout_params]),
    ])
