# Mistake: a PushROSNamespace of its own; robot.launch.py's required robot_name not passed.
# Verdict names: pass 'robot_name'
from launch import LaunchContext, LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.actions import OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import PushROSNamespace
from launch_ros.substitutions import FindPackageShare


def scouts(context: LaunchContext) -> list[GroupAction]:
    count = int(LaunchConfiguration('robot_count').perform(context))
    robot = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                  'robot.launch.py'])
    return [GroupAction([
                PushROSNamespace(f'scout{number}'),
                IncludeLaunchDescription(PythonLaunchDescriptionSource(robot),
                                         launch_arguments={'sensor_rate': '5.0'}.items())])
            for number in range(1, count + 1)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='2'),
        OpaqueFunction(function=scouts),
    ])
