"""Exercise 6.13.1 (solution): a rover of rover_config in the warehouse.

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
        [PathJoinSubstitution([config, 'robots', robot]), '.yaml'],
        # [START site_layer]
        # last, so the warehouse wins over the robot's file
        PathJoinSubstitution([FindPackageShare('my_ws_exercises'), 'config',
                              'ex613_warehouse.yaml']),
        # [END site_layer]
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
