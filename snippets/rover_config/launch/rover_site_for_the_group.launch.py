"""A tempting mistake (lesson 6.13): the site's file given to the whole group
with SetParametersFromFile, and each node's own layers after it.

    ros2 launch rover_config rover_site_for_the_group.launch.py
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node, PushROSNamespace, SetParametersFromFile
from launch_ros.parameter_descriptions import ParameterFile
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    config = PathJoinSubstitution([FindPackageShare('rover_config'), 'config'])
    # [START group]
    own_layers = [
        ParameterFile(PathJoinSubstitution([config, 'defaults.yaml']), allow_substs=True),
        PathJoinSubstitution([config, 'robots', 'scout.yaml']),
    ]
    scout = GroupAction([
        PushROSNamespace('scout'),
        # the lab's file for every node of the group ...
        SetParametersFromFile(PathJoinSubstitution([config, 'sites', 'lab.yaml'])),
        # ... and the node's own layers
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             parameters=own_layers),
    ])
    # [END group]
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='scout'),  # $(var robot) in defaults.yaml
        scout,
    ])
