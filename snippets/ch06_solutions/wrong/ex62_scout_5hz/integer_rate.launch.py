# Mistake: update_rate given as 5, an integer, for a DOUBLE parameter (the node refuses it and dies)
# Verdict names: expecting type 'DOUBLE'
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    scout_params = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'robot_params.yaml'])
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             output='screen', parameters=[scout_params, {'update_rate': 5}]),
    ])
