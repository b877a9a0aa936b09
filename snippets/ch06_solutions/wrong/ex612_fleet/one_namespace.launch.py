# Mistake: every scout is given the same robot_name, so all of them run in one namespace.
# Verdict names: processes run as the node /scout/sensor_publisher
from launch import LaunchContext, LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.actions import OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def scouts(context: LaunchContext) -> list[GroupAction]:
    count = int(LaunchConfiguration('robot_count').perform(context))
    robot = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                  'robot.launch.py'])
    return [GroupAction([IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot),
                launch_arguments={'robot_name': 'scout', 'sensor_rate': '5.0'}.items())])
            for _ in range(count)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='2'),
        OpaqueFunction(function=scouts),
    ])
