# Mistake: both includes share one GroupAction: the scope ends after the second include, so
#   robot1's robot_name is still set for robot2.
# Verdict names: /robot2/robot_controller got robot_name 'alpha', expected 'scout'
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot_instance = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'launch', 'robot_instance.launch.py'])
    return LaunchDescription([
        GroupAction([
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot_instance),
                launch_arguments={'robot_ns': 'robot1', 'robot_name': 'alpha'}.items(),
            ),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot_instance),
                launch_arguments={'robot_ns': 'robot2'}.items(),
            ),
        ]),
    ])
