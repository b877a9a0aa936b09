"""Test launch file: a namespaced group with global parameters and remaps, a node
outside it, and entities whose effect is only known while the launch runs."""
from launch import LaunchDescription
from launch.actions import (
    DeclareLaunchArgument,
    GroupAction,
    LogInfo,
    OpaqueFunction,
    RegisterEventHandler,
    TimerAction,
)
from launch.event_handlers import OnProcessStart
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap


def generate_launch_description():
    lidar = Node(package='my_robot_pkg', executable='sensor_publisher', name='lidar',
                 remappings=[('distance', 'scan')])
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='robot1'),
        GroupAction([
            PushRosNamespace(LaunchConfiguration('robot')),
            SetParameter(name='use_sim_time', value=True),
            SetRemap(src='distance_filtered', dst='/filtered'),
            lidar,
            Node(package='my_robot_pkg', executable='data_processor', name='filter',
                 remappings=[('distance', 'scan')], parameters=[{'window_size': 5}]),
        ]),
        Node(package='my_robot_pkg', executable='robot_controller', name='controller',
             parameters=[{'update_rate': 20.0, 'max_linear_sped': 0.3}]),
        OpaqueFunction(function=lambda context: []),
        TimerAction(period=1.0, actions=[
            Node(package='my_robot_pkg', executable='data_processor', name='late')]),
        RegisterEventHandler(OnProcessStart(target_action=lidar,
                                            on_start=[LogInfo(msg='lidar up')])),
    ])
