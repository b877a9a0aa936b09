"""Exercise 6.3.2: bringup_twice.launch.py without the surprise.

Each include sits in its own GroupAction.  A GroupAction is scoped: launch
configurations set inside it (here: the include's launch arguments) are
forgotten when it ends, so robot2 gets the default robot_name again.
"""
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
        ]),
        GroupAction([
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot_instance),
                launch_arguments={'robot_ns': 'robot2'}.items(),
            ),
        ]),
    ])
