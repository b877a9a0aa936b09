"""Exercise 7.2.1: the capstone with a list of robots instead of a count.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex72_my_capstone.launch.py robots:=turtle1,turtle3

Lesson 7.2 has the task; capstone_bringup's capstone.launch.py is the model.
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction,  # noqa: F401  (you will need them)
                            IncludeLaunchDescription, OpaqueFunction)
from launch.launch_description_sources import PythonLaunchDescriptionSource  # noqa: F401
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution  # noqa: F401
from launch_ros.substitutions import FindPackageShare  # noqa: F401


def system(context: LaunchContext) -> list:
    """The simulator once, then one robot per name in the list."""
    # TODO: read the argument robots (LaunchConfiguration('robots').perform(context))
    #       and split it at the commas into turtle names.
    # TODO: include capstone_bringup's launch/sim.launch.py once, with robot_count
    #       = the highest turtle number in the list (turtle3 -> '3').
    # TODO: include capstone_bringup's launch/robot.launch.py once per name, with
    #       robot:=<name>, each include in a GroupAction(scoped=True) of its own.
    return []


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robots', default_value='turtle1,turtle2',
                              description='The turtles to drive, comma-separated'),
        OpaqueFunction(function=system),
    ])
