# Mistake: the forbidden shortcut: robot_name 'scout' is written into the second include
#   instead of scoping the first one. robot2 is called scout, but no longer follows the
#   default of robot_instance.launch.py nor robot_name:=... on the command line.
# Verdict names: got robot_name 'scout', expected 'bravo' from robot_name:=bravo
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
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
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot_instance),
            launch_arguments={'robot_ns': 'robot2', 'robot_name': 'scout'}.items(),
        ),
    ])
