# Mistake: the includes are swapped, so robot2 starts before robot1 has set robot_name: a
#   third robot added after robot1 would be called alpha again.
# Verdict names: robot1 must be included first
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
            launch_arguments={'robot_ns': 'robot2'}.items(),
        ),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot_instance),
            launch_arguments={'robot_ns': 'robot1', 'robot_name': 'alpha'}.items(),
        ),
    ])
