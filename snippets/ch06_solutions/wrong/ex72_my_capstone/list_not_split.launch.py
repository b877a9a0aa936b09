# Mistake: the list is not split: the whole text turtle1,turtle3 goes to one include as
#   its robot name.
# Verdict names: split the list at the commas
from launch import LaunchContext, LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription,
                            OpaqueFunction)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def capstone_file(name: str) -> PythonLaunchDescriptionSource:
    return PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('capstone_bringup'), 'launch', name]))


def system(context: LaunchContext) -> list:
    """The simulator once, then one scoped robot per name in the list."""
    text = LaunchConfiguration('robots').perform(context)
    names = [text]
    highest = max(int(name.removeprefix('turtle')) for name in text.split(','))
    simulator = IncludeLaunchDescription(
        capstone_file('sim.launch.py'), launch_arguments={'robot_count': str(highest)}.items())
    robots = [GroupAction(scoped=True, actions=[IncludeLaunchDescription(
                  capstone_file('robot.launch.py'), launch_arguments={'robot': name}.items())])
              for name in names]
    return [simulator, *robots]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robots', default_value='turtle1,turtle2',
                              description='The turtles to drive, comma-separated'),
        OpaqueFunction(function=system),
    ])
