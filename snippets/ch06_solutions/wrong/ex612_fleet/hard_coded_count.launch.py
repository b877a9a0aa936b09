# Mistake: two scouts written out; robot_count is declared but never read.
# Verdict names: robot_count:=3
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def scout(name: str) -> GroupAction:
    robot = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                  'robot.launch.py'])
    return GroupAction([IncludeLaunchDescription(
        PythonLaunchDescriptionSource(robot),
        launch_arguments={'robot_name': name, 'sensor_rate': '5.0'}.items())])


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='2'),
        scout('scout1'),
        scout('scout2'),
    ])
