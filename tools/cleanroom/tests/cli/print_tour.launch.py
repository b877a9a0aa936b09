"""A tour of what `ros2 launch -p` describes; print_tour.expected is what Jazzy printed for it.

Nodes (named, unnamed, namespace '', ros_arguments), a process with cwd/env/shell,
actions -p does not expand (group, include, timer, opaque function), substitutions,
events and nested event handlers, a handler last so the tree's odd last lines show.
"""
from launch import LaunchDescription
from launch.actions import (
    DeclareLaunchArgument,
    EmitEvent,
    ExecuteProcess,
    GroupAction,
    IncludeLaunchDescription,
    LogInfo,
    OpaqueFunction,
    RegisterEventHandler,
    SetEnvironmentVariable,
    Shutdown,
    TimerAction,
)
from launch.conditions import IfCondition
from launch.event_handlers import OnProcessExit, OnProcessStart, OnShutdown
from launch.events.process import ShutdownProcess
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (
    EqualsSubstitution,
    LaunchConfiguration,
    NotSubstitution,
    OrSubstitution,
    PathJoinSubstitution,
    PythonExpression,
)
from launch_ros.actions import Node, PushRosNamespace, SetParameter
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    worker = ExecuteProcess(cmd=['sleep', LaunchConfiguration('seconds')], name='worker',
                            cwd='/tmp', env={'MODE': 'fast'}, shell=True)
    config = PathJoinSubstitution([FindPackageShare('demo_pkg'), 'config', 'params.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('seconds', default_value='1'),
        Node(package='demo_pkg', executable='talker', name='talker', namespace='robot',
             parameters=[{'rate': 10.0}, config], remappings=[('chatter', 'out')],
             arguments=['--verbose'], output='screen'),
        Node(package='demo_pkg', executable='listener', namespace='',
             ros_arguments=['--log-level', 'debug']),
        worker,
        SetEnvironmentVariable('ROBOT', 'one'),
        GroupAction([PushRosNamespace('fleet'), SetParameter('use_sim_time', True),
                     Node(package='demo_pkg', executable='talker')],
                    condition=IfCondition(LaunchConfiguration('fleet', default='true'))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('demo_pkg'), 'launch', 'more.launch.py']))),
        TimerAction(period=2.0, actions=[LogInfo(msg='later')]),
        LogInfo(msg=['seconds: ', LaunchConfiguration('seconds'), ' in ', config]),
        LogInfo(msg=PythonExpression([LaunchConfiguration('seconds'), ' * 2'])),
        LogInfo(msg=NotSubstitution(LaunchConfiguration('fleet', default='true'))),
        LogInfo(msg=OrSubstitution('true', EqualsSubstitution(LaunchConfiguration('seconds'), 1))),
        OpaqueFunction(function=lambda context: []),
        EmitEvent(event=ShutdownProcess(process_matcher=lambda action: False)),
        RegisterEventHandler(OnProcessStart(target_action=worker,
                                            on_start=[LogInfo(msg='worker started')])),
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg='bye')])),
        RegisterEventHandler(OnProcessExit(target_action=worker, on_exit=[
            LogInfo(msg='worker done'),
            RegisterEventHandler(OnProcessExit(on_exit=[LogInfo(msg='any exit'),
                                                        Shutdown(reason='done')])),
        ])),
    ])
