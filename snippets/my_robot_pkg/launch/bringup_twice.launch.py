"""Two robots from one file: robot_instance.launch.py included twice.

The second include gives no robot_name, so you would expect the default,
"scout".  Run it and see what robot2 is really called.
"""
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # [START path]
    robot_instance = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'launch', 'robot_instance.launch.py'])
    # [END path]
    return LaunchDescription([
        # [START includes]
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot_instance),
            launch_arguments={'robot_ns': 'robot1', 'robot_name': 'alpha'}.items(),
        ),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot_instance),
            launch_arguments={'robot_ns': 'robot2'}.items(),  # robot_name: default?
        ),
        # [END includes]
    ])
