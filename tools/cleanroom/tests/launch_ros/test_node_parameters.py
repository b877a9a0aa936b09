"""Node parameters: temp files, keys, typing, parameter files (goldens 02-04, 13, 25)."""
import os

import pytest
from launch.actions import DeclareLaunchArgument, GroupAction, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, TextSubstitution
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.parameter_descriptions import Parameter, ParameterFile, ParameterValue
from launch_ros.substitutions import FindPackageShare
from launch_ros.utilities import param_files

PKG = 'lr_test_pkg'


def params_files(cmd):
    return [item for prev, item in zip(cmd[:-1], cmd[1:], strict=True) if prev == '--params-file']


def only_params(cmd):
    (entry,) = params_files(cmd)
    ((key, body),) = entry['content'].items()
    return key, body['ros__parameters'], entry['path']


def test_dict_is_flattened_typed_and_keyed_by_wildcard(test_package, run_launch):
    record = run_launch([Node(package=PKG, executable='noop', name='ctrl', parameters=[{
        'robot_name': 'my_robot', 'rate': 10.0, 'retries': 3, 'enabled': True,
        'answer': 'yes', 'sensors': ['lidar', 'camera'], 'weights': (1, 2, 3),
        'limits': {'linear': 0.5, 'angular': {'max': 1.0}},
    }])])
    key, params, path = only_params(record.node_cmd('ctrl'))
    assert key == '/**'
    assert os.path.basename(path).startswith('launch_params_')
    assert params == {'robot_name': 'my_robot', 'rate': 10.0, 'retries': 3, 'enabled': True,
                      'answer': 'yes', 'sensors': ['lidar', 'camera'], 'weights': [1, 2, 3],
                      'limits.linear': 0.5, 'limits.angular.max': 1.0}
    assert isinstance(params['rate'], float)


def test_full_name_key_when_name_and_namespace(test_package, run_launch):
    record = run_launch([Node(package=PKG, executable='noop', name='driver', namespace='robot_0',
                              parameters=[{'rate_hz': 1.0}])])
    key, params, _ = only_params(record.node_cmd('driver'))
    assert key == '/robot_0/driver'
    assert params == {'rate_hz': 1.0}


UNSET = object()


@pytest.mark.parametrize('name, namespace, pushed, key', [
    ('n', 'ns', None, '/ns/n'),
    ('n', UNSET, None, '/**'),
    (UNSET, 'ns', None, '/**'),
    (UNSET, UNSET, None, '/**'),
    ('n', '/abs', None, '/abs/n'),
    ('n', '', None, '/n'),
    ('n', '/', None, '/n'),
    ('n', 'a/b', None, '/a/b/n'),
    ('n', UNSET, 'grp', '/grp/n'),
    (UNSET, UNSET, 'grp', '/**'),
    ('n', 'ns', 'grp', '/grp/ns/n'),
    ('n', '', 'grp', '/grp/n'),
])
def test_dict_file_is_keyed_by_the_full_name_once_name_and_namespace_are_known(
        test_package, run_launch, name, namespace, pushed, key):
    """Observed on Jazzy (the file a node got, printed by the node): the key is the
    node's full name when it has a name and a namespace (its own, pushed or ''),
    else '/**'; the values sit under `ros__parameters`.
    """
    texts = []

    def read_file(event, context):
        path = event.cmd[event.cmd.index('--params-file') + 1]
        with open(path) as handle:
            texts.append(handle.read())

    keywords = {kw: value for kw, value in (('name', name), ('namespace', namespace))
                if value is not UNSET}
    node = Node(package=PKG, executable='noop', parameters=[{'a': 1}], **keywords)
    entities = [node] if pushed is None else [GroupAction([PushRosNamespace(pushed), node])]
    run_launch([RegisterEventHandler(OnProcessStart(on_start=read_file)), *entities])
    assert texts == [f'{key}:\n  ros__parameters:\n    a: 1\n']


def test_substitution_values_are_typed_by_yaml(test_package, run_launch):
    args = [DeclareLaunchArgument(name, default_value=value) for name, value in (
        ('serial', '007'), ('octal', '042'), ('flag', 'true'), ('count', '3'), ('ratio', '2.0'),
        ('ids', '[1, 2, 3]'), ('word', 'hello'))]
    lc = LaunchConfiguration
    record = run_launch([*args, Node(package=PKG, executable='noop', name='typed', parameters=[{
        'serial': lc('serial'), 'octal': lc('octal'), 'flag': lc('flag'), 'count': lc('count'),
        'ratio': lc('ratio'), 'ids': lc('ids'), 'word': lc('word'),
        'label': [TextSubstitution(text='robot_'), lc('flag')],
        'serial_str': ParameterValue(lc('serial'), value_type=str),
        'ratio_f': ParameterValue(lc('count'), value_type=float),
        'ids_f': ParameterValue(lc('ids'), value_type=list[float]),
        'as_text': ParameterValue('[1, 2, 3]'),
        # Items of one type: Jazzy refuses [[count], [ratio]] (3 then 2.0), observed.
        'pair': [[lc('count')], [lc('count'), '0']],
        'concat': [lc('count'), lc('ratio')],
    }])])
    _, params, _ = only_params(record.node_cmd('typed'))
    assert params == {'serial': 7, 'octal': 34, 'flag': True, 'count': 3, 'ratio': 2.0,
                      'ids': [1, 2, 3], 'word': 'hello', 'label': 'robot_true',
                      'serial_str': '007', 'ratio_f': 3.0, 'ids_f': [1.0, 2.0, 3.0],
                      'as_text': '[1, 2, 3]', 'pair': [3, 30], 'concat': 32.0}
    assert isinstance(params['ratio_f'], float)


def test_files_and_dicts_keep_order_and_parameter_gives_dash_p(test_package, run_launch):
    wildcard = PathJoinSubstitution([FindPackageShare(PKG), 'config', 'wildcard.yaml'])
    record = run_launch([Node(package=PKG, executable='noop', name='layered', parameters=[
        wildcard, {'level': 5}, Parameter('gain', LaunchConfiguration('g', default='2.5')),
    ])])
    cmd = record.node_cmd('layered')
    files = params_files(cmd)
    assert files[0]['path'] == str(test_package / 'share' / PKG / 'config' / 'wildcard.yaml')
    assert files[0]['content'] == {'/**': {'ros__parameters': {'level': 2}}}
    assert files[1]['content'] == {'/**': {'ros__parameters': {'level': 5}}}
    assert cmd[-2:] == ['-p', 'gain:=2.5']


def test_missing_parameter_file_is_dropped_with_a_warning(test_package, run_launch, capfd):
    missing = str(test_package / 'share' / PKG / 'config' / 'nope.yaml')
    record = run_launch([Node(package=PKG, executable='noop', name='p', parameters=[missing])])
    assert record.node_cmd('p')[1:] == ['--ros-args', '-r', '__node:=p']
    out = capfd.readouterr()
    assert (f'[WARNING] [launch_ros.actions.node]: Parameter file path is not a file: {missing}'
            in out.out + out.err)


def test_parameter_file_with_substitutions(test_package, run_launch, monkeypatch):
    monkeypatch.setenv('LR_TEST_HOME', '/home/robot')
    source = PathJoinSubstitution([FindPackageShare(PKG), 'config', 'substs.yaml'])
    record = run_launch([
        DeclareLaunchArgument('robot', default_value='bot_a'),
        Node(package=PKG, executable='noop', name='typed', parameters=[
            ParameterFile(source, allow_substs=True), ParameterFile(source)]),
    ], argv=('robot:=bot_b',))
    substituted, verbatim = params_files(record.node_cmd('typed'))
    assert os.path.basename(substituted['path']).startswith('launch_params_')
    assert substituted['content'] == {'/**': {'ros__parameters': {
        'robot_name': 'bot_b', 'home': '/home/robot',
        'share': str(test_package / 'share' / PKG), 'speed': 1.25}}}
    assert verbatim['path'] == str(test_package / 'share' / PKG / 'config' / 'substs.yaml')


def test_a_dictionary_file_stays_and_a_substituted_file_goes_when_the_launch_ends(
        test_package, run_launch, monkeypatch):
    """Observed on Jazzy: the `launch_params_*` file of a parameter dictionary stays in
    the temporary folder after the launch; the one ParameterFile(allow_substs=True)
    wrote is removed."""
    monkeypatch.setenv('LR_TEST_HOME', '/home/robot')
    record = run_launch([
        DeclareLaunchArgument('robot', default_value='bot_a'),
        Node(package=PKG, executable='noop', name='t', parameters=[{'a': 1}]),
        Node(package=PKG, executable='noop', name='s', parameters=[ParameterFile(
            str(test_package / 'share' / PKG / 'config' / 'substs.yaml'), allow_substs=True)]),
    ])
    _, _, kept = only_params(record.node_cmd('t'))
    _, _, removed = only_params(record.node_cmd('s'))
    assert os.path.exists(kept)
    os.unlink(kept)
    assert not os.path.exists(removed)
    assert param_files.temporary_files() == []


def test_parameter_value_type_error_is_jazzys():
    with pytest.raises(TypeError) as info:
        ParameterValue('0.5', value_type=float)
    assert str(info.value) == "value='0.5' is not an instance of <class 'float'>"


def test_bad_parameters_argument_names_the_entry():
    # Jazzy's words (observed): an entry that is no dict is taken for a parameter file.
    with pytest.raises(TypeError, match=r"^'ParameterFile\(\)' expected 'param_file' to be one "
                       r"of \[.*\], but got '42' of type '<class 'int'>'$"):
        Node(package=PKG, executable='noop', parameters=[42])
    with pytest.raises(TypeError, match=r"^Expecting list of parameters, got \{'a': 1\}$"):
        Node(package=PKG, executable='noop', parameters={'a': 1})
