"""Exercise 6.13.1: a rover of rover_config in the warehouse.

TODO: in the warehouse, every robot's sensor publishes at 5.0 Hz and its
controller drives at most 0.4 m/s, whichever robot you start.  Write those
values in config/ex613_warehouse.yaml, and make sure they win: the robot's
own file (e.g. scout's 1.2 m/s) must not.  Check what the nodes got with
ros2 param dump.

    ros2 launch my_ws_exercises ex613_rover.launch.py robot:=ranger
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushROSNamespace, SetParameter
from launch_ros.parameter_descriptions import ParameterFile
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot = LaunchConfiguration('robot')
    config = PathJoinSubstitution([FindPackageShare('rover_config'), 'config'])
    layers = [
        ParameterFile(PathJoinSubstitution([config, 'defaults.yaml']), allow_substs=True),
        # TODO: is this the right place for the warehouse?
        PathJoinSubstitution([FindPackageShare('my_ws_exercises'), 'config',
                              'ex613_warehouse.yaml']),
        [PathJoinSubstitution([config, 'robots', robot]), '.yaml'],
    ]
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='scout',
                              description='Robot to start: config/robots/<robot>.yaml '
                                          'of rover_config'),
        GroupAction([
            PushROSNamespace(robot),
            SetParameter(name='use_sim_time', value=False),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
                 parameters=layers),
            Node(package='my_robot_pkg', executable='data_processor', output='screen',
                 parameters=layers),
            Node(package='my_robot_pkg', executable='robot_controller', output='screen',
                 parameters=layers),
        ]),
    ])
