"""Node command lines, started for real from a colcon-built package."""
import pytest
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace, PushRosNamespace

PKG = 'lr_test_pkg'


def exe(prefix):
    return str(prefix / 'lib' / PKG / 'noop')


def test_bare_node(test_package, run_launch):
    record = run_launch([Node(package=PKG, executable='noop')])
    assert record.returncode == 0
    assert record.processes[0]['name'] == 'noop-1'
    assert record.processes[0]['cmd'] == [exe(test_package), '--ros-args']


def test_arguments_ros_arguments_name_namespace_and_exec_name(test_package, run_launch):
    record = run_launch([
        Node(package=PKG, executable='noop', name='verbose', namespace='ns1',
             exec_name='my_noop', arguments=['0', LaunchConfiguration('delay', default='5')],
             ros_arguments=['--log-level', 'debug']),
    ])
    assert record.by_name('my_noop')['cmd'] == [
        exe(test_package), '0', '5', '--ros-args', '--log-level', 'debug',
        '--ros-args', '-r', '__node:=verbose', '-r', '__ns:=/ns1']


def test_process_names_count_every_process(test_package, run_launch):
    record = run_launch([Node(package=PKG, executable='noop', name=f'n{i}') for i in range(3)])
    assert sorted(p['name'] for p in record.processes) == ['noop-1', 'noop-2', 'noop-3']


def test_remappings_and_substituted_name(test_package, run_launch):
    record = run_launch([
        DeclareLaunchArgument('robot', default_value='bot'),
        Node(package=PKG, executable='noop', name=LaunchConfiguration('robot'),
             remappings=[('chatter', ['/', LaunchConfiguration('robot'), '/chatter']),
                         ('/tf', 'tf')]),
    ])
    assert record.node_cmd('bot')[2:] == [
        '-r', '__node:=bot', '-r', 'chatter:=/bot/chatter', '-r', '/tf:=tf']


def test_namespaces_push_compose_and_absolute(test_package, run_launch):
    record = run_launch([
        Node(package=PKG, executable='noop', name='top', namespace='ns1'),
        Node(package=PKG, executable='noop', name='absolute', namespace='/abs'),
        GroupAction([
            PushRosNamespace('robot1'),
            Node(package=PKG, executable='noop', name='in_group'),
            Node(package=PKG, executable='noop', name='rel', namespace='sensors'),
            Node(package=PKG, executable='noop', name='abs_in_group', namespace='/fixed'),
            GroupAction([
                PushROSNamespace('arm'),
                Node(package=PKG, executable='noop', name='nested'),
            ]),
            GroupAction([
                PushRosNamespace('/other'),
                Node(package=PKG, executable='noop', name='repushed', namespace='x'),
            ]),
        ]),
        Node(package=PKG, executable='noop', name='after_group'),
    ])
    expected = {'top': '/ns1', 'absolute': '/abs', 'in_group': '/robot1',
                'rel': '/robot1/sensors', 'abs_in_group': '/fixed', 'nested': '/robot1/arm',
                'repushed': '/other/x', 'after_group': None}
    for name, namespace in expected.items():
        tail = record.node_cmd(name)[1:]
        ns_args = ['-r', '__ns:=' + namespace] if namespace else []
        assert tail == ['--ros-args', '-r', '__node:=' + name, *ns_args], name


UNSET = object()


@pytest.mark.parametrize('namespace, pushed, expected', [
    (UNSET, None, []),
    ('', None, ['-r', '__ns:=/']),
    ('/', None, ['-r', '__ns:=/']),
    ('ns', None, ['-r', '__ns:=/ns']),
    ('/ns', None, ['-r', '__ns:=/ns']),
    ('a/b', None, ['-r', '__ns:=/a/b']),
    (UNSET, 'grp', ['-r', '__ns:=/grp']),
    ('', 'grp', ['-r', '__ns:=/grp']),
    ('ns', 'grp', ['-r', '__ns:=/grp/ns']),
    ('/ns', 'grp', ['-r', '__ns:=/ns']),
])
@pytest.mark.parametrize('name', [None, 'n'])
def test_namespace_arguments_as_jazzy_passes_them(test_package, run_launch, namespace, pushed,
                                                 expected, name):
    """Observed on Jazzy (a node printing its argv): namespace '' is the root, `-r __ns:=/`.

    Not given (None), no `__ns` at all; inside a PushRosNamespace group, '' and
    not given both take the pushed namespace.
    """
    keywords = {} if namespace is UNSET else {'namespace': namespace}
    if name is not None:
        keywords['name'] = name
    node = Node(package=PKG, executable='noop', **keywords)
    record = run_launch([node] if pushed is None else [GroupAction([PushRosNamespace(pushed),
                                                                    node])])
    name_args = [] if name is None else ['-r', '__node:=' + name]
    assert record.processes[0]['cmd'][1:] == ['--ros-args', *name_args, *expected]


def test_additional_env_and_executable_on_path(test_package, run_launch):
    record = run_launch([
        Node(executable='true', name='plain', additional_env={'LR_EXTRA': '1'}),
    ])
    process = record.by_name('true')
    assert process['cmd'][1:] == ['--ros-args', '-r', '__node:=plain']
    assert process['env']['LR_EXTRA'] == '1'


def test_condition_skips_node(test_package, run_launch):
    from launch.conditions import IfCondition

    record = run_launch([
        Node(package=PKG, executable='noop', name='skipped', condition=IfCondition('false')),
        Node(package=PKG, executable='noop', name='kept', condition=IfCondition('true')),
    ])
    assert [p['cmd'][3] for p in record.processes] == ['__node:=kept']


def test_execute_process_keywords_pass_through(test_package, run_launch):
    from launch.actions import EmitEvent, OpaqueFunction
    from launch.events import Shutdown

    exits = []

    def count(context):
        exits.append(context.locals.event.returncode)
        return [EmitEvent(event=Shutdown(reason='seen two runs'))] if len(exits) == 2 else None

    record = run_launch([
        Node(package=PKG, executable='noop', name='again', respawn=True, respawn_delay=0.0,
             output='screen', on_exit=[OpaqueFunction(function=count)]),
    ])
    assert exits[:2] == [0, 0]
    assert len(record.processes) >= 2  # a third run may start before the shutdown lands
    assert {p['name'] for p in record.processes} == {'noop-1'}
    assert all(p['cmd'] == record.processes[0]['cmd'] for p in record.processes)
