"""Exercise 6.5.2: two robots in their own namespaces, one parameter file.

    ros2 launch ch06_solutions ex65_two_robots.launch.py
"""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node, PushROSNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    settings = PathJoinSubstitution(
        [FindPackageShare('my_ws_exercises'), 'config', 'ex65_robots.yaml'])

    def robot(namespace: str) -> GroupAction:
        # The group ends the namespace with the robot: robot2 is not inside robot1.
        return GroupAction([
            PushROSNamespace(namespace),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
            Node(package='my_robot_pkg', executable='data_processor', output='screen'),
            Node(package='my_robot_pkg', executable='robot_controller', output='screen',
                 parameters=[settings]),
        ])

    return LaunchDescription([robot('robot1'), robot('robot2')])
