"""Exercise 6.3.2: two robots, each with its own name.

This is bringup_twice.launch.py of my_robot_pkg: robot1 is called alpha,
robot2 gets no robot_name and should be called by the default, scout.  As
it stands, robot2 is called alpha too.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex63_bringup_scoped.launch.py
"""
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription  # noqa: F401  (GroupAction: you will need it)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot_instance = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'launch', 'robot_instance.launch.py'])
    return LaunchDescription([
        # TODO: scope the first include, so that its robot_name is forgotten
        #       before the second include runs.  Do not give the second
        #       include a robot_name: it must keep the default of
        #       robot_instance.launch.py (or whatever the command line says).
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot_instance),
            launch_arguments={'robot_ns': 'robot1', 'robot_name': 'alpha'}.items(),
        ),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot_instance),
            launch_arguments={'robot_ns': 'robot2'}.items(),
        ),
    ])
