# Mistake: a loop over LaunchConfiguration in generate_launch_description(), too early.
# Verdict names: OpaqueFunction
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                  'robot.launch.py'])
    count = LaunchConfiguration('robot_count')
    scouts = [GroupAction([IncludeLaunchDescription(
                  PythonLaunchDescriptionSource(robot),
                  launch_arguments={'robot_name': f'scout{number}',
                                    'sensor_rate': '5.0'}.items())])
              for number in range(1, int(count) + 1)]
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='2'),
        *scouts,
    ])
