"""As many robots as robot_count asks for, each robot.launch.py in its own
namespace: a number known only at launch time, so an OpaqueFunction.

    ros2 launch robot_bringup fleet.launch.py robot_count:=3
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.actions import OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


# [START robots]
def robots(context: LaunchContext) -> list[GroupAction]:
    """Runs while the launch runs, when robot_count has its value."""
    count = int(LaunchConfiguration('robot_count').perform(context))
    robot = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                  'robot.launch.py'])
    return [GroupAction([IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot),
                launch_arguments={'robot_name': f'robot{number}'}.items())])
            for number in range(1, count + 1)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='2',
                              description='How many robots to start'),
        OpaqueFunction(function=robots),
    ])
# [END robots]
