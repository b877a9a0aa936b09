"""Node command-line order (goldens 01, 06, 07, 12, 17)."""
from launch_ros.utilities.command_line import (
    ParamArg,
    ParamFileArg,
    global_parameter_entries,
    node_command_line,
)


def test_bare_node_still_gets_ros_args():
    assert node_command_line('/x/talker') == ['/x/talker', '--ros-args']


def test_arguments_then_ros_arguments_then_name():
    argv = node_command_line('/x/exiter', arguments=['0', '5'],
                             ros_arguments=['--log-level', 'debug'], name='verbose')
    assert argv == ['/x/exiter', '0', '5', '--ros-args', '--log-level', 'debug',
                    '--ros-args', '-r', '__node:=verbose']


def test_full_order_globals_before_own():
    globals_ = global_parameter_entries([('use_sim_time', True), '/share/wild.yaml'])
    argv = node_command_line(
        '/x/listener', name='listener', namespace='/fleet',
        parameters=globals_ + [ParamFileArg('/tmp/launch_params_1'), ParamArg('a', 1.5)],
        remappings=[('chatter', 'news'), ('/tf', 'tf')])
    assert argv == ['/x/listener', '--ros-args', '-r', '__node:=listener', '-r', '__ns:=/fleet',
                    '-p', 'use_sim_time:=True', '--params-file', '/share/wild.yaml',
                    '--params-file', '/tmp/launch_params_1', '-p', 'a:=1.5',
                    '-r', 'chatter:=news', '-r', '/tf:=tf']
