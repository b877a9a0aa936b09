# Mistake: the GroupAction is put around the second include, the one that sets nothing:
#   the first include's robot_name:=alpha is still set when the second one runs.
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
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot_instance),
            launch_arguments={'robot_ns': 'robot1', 'robot_name': 'alpha'}.items(),
        ),
        GroupAction([
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot_instance),
                launch_arguments={'robot_ns': 'robot2'}.items(),
            ),
        ]),
    ])
