"""Scoping of launch configurations and environment: groups scope, includes do not."""
from __future__ import annotations

import textwrap

from launch import LaunchDescription
from launch.actions import (
    AppendEnvironmentVariable,
    DeclareLaunchArgument,
    ExecuteProcess,
    GroupAction,
    IncludeLaunchDescription,
    LogInfo,
    ResetEnvironment,
    ResetLaunchConfigurations,
    SetEnvironmentVariable,
    SetLaunchConfiguration,
    TimerAction,
    UnsetEnvironmentVariable,
    UnsetLaunchConfiguration,
)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import EnvironmentVariable, LaunchConfiguration

COLOR = LaunchConfiguration('color', default='unset')


def test_scoped_group_restores_configurations(run_launch):
    result = run_launch([
        SetLaunchConfiguration('color', 'red'),
        GroupAction([SetLaunchConfiguration('color', 'blue'), LogInfo(msg=['in: ', COLOR])]),
        LogInfo(msg=['after scoped: ', COLOR]),
        GroupAction([SetLaunchConfiguration('color', 'green')], scoped=False),
        LogInfo(msg=['after unscoped: ', COLOR]),
    ])
    assert result.user_lines() == ['in: blue', 'after scoped: red', 'after unscoped: green']


def test_group_forwarding_and_given_configurations(run_launch):
    other = LaunchConfiguration('other', default='missing')
    result = run_launch([
        SetLaunchConfiguration('color', 'red'),
        SetLaunchConfiguration('other', 'kept'),
        GroupAction([LogInfo(msg=[COLOR, ' ', other])], forwarding=False,
                    launch_configurations={'color': ['dark', COLOR]}),
        GroupAction([LogInfo(msg=[COLOR, ' ', other])],
                    launch_configurations={'color': 'yellow'}),
        LogInfo(msg=[COLOR, ' ', other]),
    ])
    assert result.user_lines() == ['darkred missing', 'yellow kept', 'red kept']


def test_unset_and_reset_configurations(run_launch):
    result = run_launch([
        SetLaunchConfiguration('color', 'red'),
        UnsetLaunchConfiguration('color'),
        LogInfo(msg=COLOR),
        SetLaunchConfiguration('color', 'red'),
        ResetLaunchConfigurations({'shade': COLOR}),
        LogInfo(msg=[COLOR, ' ', LaunchConfiguration('shade')]),
    ])
    assert result.user_lines() == ['unset', 'unset red']


def test_environment_is_scoped_like_configurations(run_launch):
    zone = EnvironmentVariable('CR_ZONE', default_value='none')
    result = run_launch([
        GroupAction([SetEnvironmentVariable('CR_ZONE', 'inner'), LogInfo(msg=zone)]),
        LogInfo(msg=zone),
        SetEnvironmentVariable('CR_ZONE', 'outer'),
        AppendEnvironmentVariable('CR_ZONE', 'more'),
        AppendEnvironmentVariable('CR_ZONE', 'first', prepend=True, separator=','),
        LogInfo(msg=zone),
        UnsetEnvironmentVariable('CR_ZONE'),
        LogInfo(msg=zone),
        SetEnvironmentVariable('CR_ZONE', 'again'),
        ResetEnvironment(),
        LogInfo(msg=zone),
    ])
    assert result.user_lines() == ['inner', 'none', 'first,outer:more', 'none', 'none']


def test_processes_get_scoped_environment_plus_additional_env(run_launch):
    result = run_launch([
        SetEnvironmentVariable('CR_A', 'a'),
        GroupAction([
            SetEnvironmentVariable('CR_B', 'b'),
            ExecuteProcess(cmd=['true'], name='inside', additional_env={'CR_C': 'c'}),
        ]),
        ExecuteProcess(cmd=['true'], name='outside'),
        ExecuteProcess(cmd=['true'], name='replaced',
                       env={'CR_ONLY': '1', 'PATH': '/usr/bin:/bin'}),
    ])
    envs = {p['name']: {k: v for k, v in p['env'].items() if k.startswith('CR_')}
            for p in result.processes}
    assert envs == {'inside-1': {'CR_A': 'a', 'CR_B': 'b', 'CR_C': 'c'},
                    'outside-2': {'CR_A': 'a'}, 'replaced-3': {'CR_ONLY': '1'}}


def _child_file(tmp_path):
    child = tmp_path / 'child.launch.py'
    child.write_text(textwrap.dedent("""
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, LogInfo
        from launch.substitutions import LaunchConfiguration, ThisLaunchFile

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('who', default_value='child'),
                DeclareLaunchArgument('rate', description='Publishing rate in Hz'),
                LogInfo(msg=[LaunchConfiguration('who'), ' ', LaunchConfiguration('rate'),
                             ' ', ThisLaunchFile()]),
            ])
    """))
    return child


def test_include_arguments_stay_set_after_the_include(run_launch, tmp_path):
    child = str(_child_file(tmp_path))
    parent = tmp_path / 'parent.launch.py'
    parent.write_text('')
    result = run_launch([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                 launch_arguments={'who': 'kid', 'rate': '5'}.items()),
        LogInfo(msg=['after: ', LaunchConfiguration('who')]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                 launch_arguments=[('rate', '2')]),
        GroupAction([IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                              launch_arguments=[('who', 'scoped'),
                                                                ('rate', '1')])]),
        LogInfo(msg=['end: ', LaunchConfiguration('who')]),
    ])
    assert result.returncode == 0
    assert result.user_lines() == [f'kid 5 {child}', 'after: kid', f'kid 2 {child}',
                                   f'scoped 1 {child}', 'end: kid']


def test_this_launch_file_after_an_include_names_the_included_file(run_launch, tmp_path):
    # Jazzy does not restore the locals after an include (frontends golden 33_xml_include).
    child = _child_file(tmp_path)
    parent = tmp_path / 'parent.launch.py'
    parent.write_text(textwrap.dedent(f"""
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription, LogInfo, TimerAction
        from launch.launch_description_sources import PythonLaunchDescriptionSource
        from launch.substitutions import ThisLaunchFile

        def generate_launch_description():
            return LaunchDescription([
                IncludeLaunchDescription(PythonLaunchDescriptionSource({str(child)!r}),
                                         launch_arguments=[('rate', '3')]),
                LogInfo(msg=['parent ', ThisLaunchFile()]),
                TimerAction(period=0.01, actions=[LogInfo(msg=['timer ', ThisLaunchFile()])]),
            ])
    """))
    result = run_launch([IncludeLaunchDescription(PythonLaunchDescriptionSource(str(parent)))])
    assert result.user_lines() == [f'child 3 {child}', f'parent {child}', f'timer {child}']


def test_timer_actions_keep_the_scope_they_were_declared_in(run_launch):
    result = run_launch([
        SetLaunchConfiguration('color', 'red'),
        GroupAction([
            SetLaunchConfiguration('color', 'blue'),
            TimerAction(period=0.05, actions=[LogInfo(msg=['timer: ', COLOR])]),
        ]),
        LogInfo(msg=['now: ', COLOR]),
    ])
    assert result.user_lines() == ['now: red', 'timer: blue']


def test_declare_launch_argument_default_and_argv(run_launch):
    declare = [DeclareLaunchArgument('color', default_value='red'),
               LogInfo(msg=COLOR)]
    assert run_launch(declare).user_lines() == ['red']
    assert run_launch(declare, argv=('color:=blue',)).user_lines() == ['blue']


def test_launch_description_lists_arguments_including_conditional_ones(tmp_path):
    from launch.conditions import IfCondition

    child = _child_file(tmp_path)
    description = LaunchDescription([
        DeclareLaunchArgument('a', default_value='1'),
        GroupAction([DeclareLaunchArgument('b')], condition=IfCondition('true')),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(str(child))),
        DeclareLaunchArgument('a', default_value='again'),
    ])
    arguments = description.get_launch_arguments()
    assert [a.name for a in arguments] == ['a', 'b', 'who', 'rate']
    assert [a._conditionally_included for a in arguments] == [False, True, False, False]
