# Mistake: the robots' includes are not scoped: robot_params, which robot.launch.py sets
#   from the first robot's name, is still set when the second include runs.
# Verdict names: /turtle3/patrol_planner patrols
from launch import LaunchContext, LaunchDescription
from launch.actions import (DeclareLaunchArgument, IncludeLaunchDescription,
                            OpaqueFunction)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def capstone_file(name: str) -> PythonLaunchDescriptionSource:
    return PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('capstone_bringup'), 'launch', name]))


def system(context: LaunchContext) -> list:
    """The simulator once, then one scoped robot per name in the list."""
    names = [name.strip() for name in LaunchConfiguration('robots').perform(context).split(',')]
    highest = max(int(name.removeprefix('turtle')) for name in names)
    simulator = IncludeLaunchDescription(
        capstone_file('sim.launch.py'), launch_arguments={'robot_count': str(highest)}.items())
    robots = [IncludeLaunchDescription(
                  capstone_file('robot.launch.py'), launch_arguments={'robot': name}.items())
              for name in names]
    return [simulator, *robots]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robots', default_value='turtle1,turtle2',
                              description='The turtles to drive, comma-separated'),
        OpaqueFunction(function=system),
    ])
