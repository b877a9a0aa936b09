"""One rover at one site: the configuration is chosen by argument and layered
(package defaults, then the robot's file, then the site's file); lesson 6.13.

    ros2 launch rover_config rover.launch.py --show-args
    ros2 launch rover_config rover.launch.py robot:=ranger site:=field

A new robot or site is a new file in config/robots/ or config/sites/; this
file and its arguments stay as they are.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushROSNamespace, SetParameter
from launch_ros.parameter_descriptions import ParameterFile
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    # [START arguments]
    arguments = [
        DeclareLaunchArgument('robot', default_value='scout',
                              description='Robot to start: its namespace, and '
                                          'config/robots/<robot>.yaml'),
        DeclareLaunchArgument('site', default_value='lab',
                              description='Where it runs: config/sites/<site>.yaml'),
        DeclareLaunchArgument('use_sim_time', default_value='false',
                              choices=['true', 'false'],
                              description='Follow /clock (a simulator) instead of the '
                                          'wall clock'),
    ]
    # [END arguments]
    robot = LaunchConfiguration('robot')
    site = LaunchConfiguration('site')

    # [START layers]
    config = PathJoinSubstitution([FindPackageShare('rover_config'), 'config'])
    layers = [
        # 1. package defaults; $(var robot) in the file becomes the argument's value
        ParameterFile(PathJoinSubstitution([config, 'defaults.yaml']), allow_substs=True),
        # 2. the robot's file, chosen by the argument `robot`
        [PathJoinSubstitution([config, 'robots', robot]), '.yaml'],
        # 3. the site's file, chosen by the argument `site`: applied last
        [PathJoinSubstitution([config, 'sites', site]), '.yaml'],
    ]
    # [END layers]

    # [START nodes]
    rover = GroupAction([
        PushROSNamespace(robot),
        # one global for every node of the group, without touching any file
        SetParameter(name='use_sim_time', value=LaunchConfiguration('use_sim_time')),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=layers),
        Node(package='my_robot_pkg', executable='data_processor', output='screen',
             parameters=layers),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             parameters=layers),
    ])
    # [END nodes]
    return LaunchDescription([*arguments, rover])
