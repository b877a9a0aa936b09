"""Exercise 7.2.1: the capstone with a list of robots instead of a count.

    ros2 launch my_ws_exercises ex72_my_capstone.launch.py robots:=turtle1,turtle3

The list is only known at launch time, so an OpaqueFunction splits it, as
capstone.launch.py turns robot_count into a number.  The simulator spawns
turtle2 .. turtleN for robot_count N, so it gets the highest number named.
Each robot's include sits in a scoped group of its own: the robot_params
that robot.launch.py sets for one robot is forgotten before the next.
"""
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
    names = [name.strip() for name in LaunchConfiguration('robots').perform(context).split(',')]
    highest = max(int(name.removeprefix('turtle')) for name in names)
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
