"""SetParameter, SetParametersFromFile, SetRemap, SetUseSimTime and scoping (goldens 07, 17)."""
from launch.actions import GroupAction
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import (
    Node,
    PushRosNamespace,
    SetParameter,
    SetParametersFromFile,
    SetRemap,
    SetUseSimTime,
)
from launch_ros.substitutions import FindPackageShare
from launch_ros.substitutions import Parameter as ParameterSubstitution

PKG = 'lr_test_pkg'


def test_globals_come_first_and_a_scoped_group_appends_to_the_outer_list(test_package, run_launch):
    wildcard = PathJoinSubstitution([FindPackageShare(PKG), 'config', 'wildcard.yaml'])
    record = run_launch([
        SetParameter(name='use_sim_time', value=True),
        GroupAction([
            PushRosNamespace('fleet'),
            SetParameter(name='level', value=LaunchConfiguration('lvl', default='3')),
            SetParametersFromFile(wildcard),
            SetRemap(src='chatter', dst='news'),
            Node(package=PKG, executable='noop', name='member', parameters=[{'level': 4}],
                 remappings=[('/tf', 'tf')]),
        ]),
        Node(package=PKG, executable='noop', name='outsider'),
    ])
    cmd = record.node_cmd('member')
    assert cmd[1:9] == ['--ros-args', '-r', '__node:=member', '-r', '__ns:=/fleet',
                        '-p', 'use_sim_time:=True', '-p']
    assert cmd[9] == 'level:=3'
    assert cmd[10] == '--params-file'
    assert cmd[11]['path'] == str(test_package / 'share' / PKG / 'config' / 'wildcard.yaml')
    assert cmd[12] == '--params-file'
    assert cmd[13]['content'] == {'/fleet/member': {'ros__parameters': {'level': 4}}}
    assert cmd[14:] == ['-r', 'chatter:=news', '-r', '/tf:=tf']
    # Jazzy appends to the list of global parameters in place: the list made at the
    # top is shared with the scoped group, so the group's additions reach the outsider
    # (frontends golden 32_xml_groups); remaps made only inside the group do not.
    outsider = record.node_cmd('outsider')
    assert outsider[1:8] == ['--ros-args', '-r', '__node:=outsider', '-p', 'use_sim_time:=True',
                             '-p', 'level:=3']
    assert outsider[8] == '--params-file'
    assert outsider[9]['path'] == cmd[11]['path']
    assert len(outsider) == 10


def test_unscoped_group_leaks_globals(test_package, run_launch):
    record = run_launch([
        GroupAction([SetRemap(src='a', dst='b'), SetUseSimTime(True)], scoped=False),
        Node(package=PKG, executable='noop', name='after'),
    ])
    assert record.node_cmd('after')[4:] == ['-p', 'use_sim_time:=True', '-r', 'a:=b']


def test_set_use_sim_time_types_substitutions(test_package, run_launch):
    record = run_launch([
        SetUseSimTime(LaunchConfiguration('sim', default='false')),
        Node(package=PKG, executable='noop', name='n'),
    ])
    assert record.node_cmd('n')[-2:] == ['-p', 'use_sim_time:=False']


def test_parameter_substitution_reads_set_parameter(test_package, run_launch):
    record = run_launch([
        SetParameter(name='robot', value='r2'),
        Node(package=PKG, executable='noop', name=ParameterSubstitution('robot')),
    ])
    assert record.node_cmd('r2')[2:4] == ['-r', '__node:=r2']
