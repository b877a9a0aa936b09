"""Actions: the entities of a launch description that do something."""
from .declare_launch_argument import DeclareLaunchArgument
from .environment_actions import (
                                  AppendEnvironmentVariable,
                                  SetEnvironmentVariable,
                                  UnsetEnvironmentVariable,
)
from .event_handler_actions import EmitEvent, RegisterEventHandler, Shutdown, UnregisterEventHandler
from .execute_process import ExecuteProcess
from .group_action import GroupAction
from .include_launch_description import IncludeLaunchDescription
from .launch_configuration_actions import SetLaunchConfiguration, UnsetLaunchConfiguration
from .log_info import LogInfo
from .opaque_coroutine import OpaqueCoroutine
from .opaque_function import OpaqueFunction
from .scope_actions import (
                                  PopEnvironment,
                                  PopLaunchConfigurations,
                                  PushEnvironment,
                                  PushLaunchConfigurations,
                                  ResetEnvironment,
                                  ResetLaunchConfigurations,
)
from .timer_action import TimerAction

__all__ = [
    'AppendEnvironmentVariable',
    'DeclareLaunchArgument',
    'EmitEvent',
    'ExecuteProcess',
    'GroupAction',
    'IncludeLaunchDescription',
    'LogInfo',
    'OpaqueCoroutine',
    'OpaqueFunction',
    'PopEnvironment',
    'PopLaunchConfigurations',
    'PushEnvironment',
    'PushLaunchConfigurations',
    'RegisterEventHandler',
    'ResetEnvironment',
    'ResetLaunchConfigurations',
    'SetEnvironmentVariable',
    'SetLaunchConfiguration',
    'Shutdown',
    'TimerAction',
    'UnregisterEventHandler',
    'UnsetEnvironmentVariable',
    'UnsetLaunchConfiguration',
]
