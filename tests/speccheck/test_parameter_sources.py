"""Where the static check finds parameters: files (scoped, nested, wildcard keys),
SetUseSimTime, ros_arguments; and how values are judged against a spec."""
from __future__ import annotations

from array import array

import pytest
from speccheck import Status, check_static, load_spec
from speccheck.launch_walk import walk_launch_file
from speccheck.param_files import ParameterFileError, read_blocks
from speccheck.spec import ParameterSpec
from speccheck.values import judge, ros_type, show

from tests.speccheck.conftest import LAUNCH_FILES

SPEC = """\
nodes:
  /robot1/lidar:
    parameters:
      publish_rate: {type: double, value: 4.0}
      use_sim_time: {type: bool, value: true}
  /robot1/filter:
    parameters:
      window_size: {type: integer, value: 7}
      use_sim_time: {type: bool}
  /robot2/controller:
    parameters:
      update_rate: {type: double, value: 15.0}
      sensors.lidar.topic: {type: string, value: rear_scan}
      enabled_sensors: {type: string_array, value: [lidar]}
topics:
  /robot1/scan:
    subscribers: [/robot1/filter]
"""


@pytest.fixture
def report(sourced, write_spec):
    return check_static(load_spec(write_spec(SPEC)), LAUNCH_FILES / 'files.launch.py')


def found(report, requirement):
    return [(f.status, f.evidence) for f in report.findings if f.requirement == requirement]


def test_every_parameter_source_is_followed(report):
    report.assert_ok()
    [(_, lidar_rate)] = found(report, 'node /robot1/lidar: parameter publish_rate')
    assert lidar_rate == 'set to 4.0 (from SetParametersFromFile params.yaml key /robot1/lidar)'
    [(_, sim_time)] = found(report, 'node /robot1/lidar: parameter use_sim_time')
    assert 'SetUseSimTime' in sim_time
    # ros_arguments come first on the node's command line: the file's 7 wins over -p 9
    [(_, window)] = found(report, 'node /robot1/filter: parameter window_size')
    assert window == 'set to 7 (from SetParametersFromFile params.yaml key /robot1/filter)'
    [(_, topic)] = found(report, 'node /robot2/controller: parameter sensors.lidar.topic')
    assert topic == "set to 'rear_scan' (from params.yaml key /**/controller)"
    [(_, sensors)] = found(report, 'node /robot2/controller: parameter enabled_sensors')
    assert sensors == "set to ['lidar'] (from the Node's parameters)"  # a Parameter(...)
    [(status, wiring)] = found(report, 'topic /robot1/scan: subscriber /robot1/filter')
    assert (status, wiring) == (Status.MET, 'remap distance:=/robot1/scan gives /robot1/scan')


def test_scoped_file_and_sim_time_stay_in_their_group(sourced):
    system = walk_launch_file(LAUNCH_FILES / 'files.launch.py')
    lidar, _, controller = system.nodes
    assert lidar.parameters()['use_sim_time'].value is True
    # the controller is outside the group: no use_sim_time, and only the keys of its own
    # file that match /robot2/controller, and its Parameter
    assert set(controller.parameters()) == {'update_rate', 'sensors.lidar.topic',
                                            'enabled_sensors'}


def test_file_keys_match_like_ros(tmp_path):
    path = tmp_path / 'p.yaml'
    path.write_text('/**:\n  ros__parameters: {a: 1}\n'
                    'ns:\n  "*":\n    ros__parameters: {b: 2}\n'
                    'node:\n  ros__parameters: {c: {d: 3}}\n')
    blocks = read_blocks(path)
    assert [(b.pattern, b.parameters) for b in blocks] == [
        ('/**', {'a': 1}), ('/ns/*', {'b': 2}), ('/node', {'c.d': 3})]
    wildcard, one_token, exact = blocks
    assert wildcard.matches('/any/depth/node') and wildcard.is_wildcard
    assert one_token.matches('/ns/x') and not one_token.matches('/ns/x/y')
    assert exact.matches('/node') and not exact.matches('/ns/node') and not exact.is_wildcard


@pytest.mark.parametrize(('text', 'message'), [
    ('- a\n', 'a parameter file is a mapping of node names'),
    ('ros__parameters: {a: 1}\n', 'ros__parameters needs a node name above it'),
    ('a: [\n', 'not valid YAML'),
])
def test_bad_parameter_files_are_named(tmp_path, text, message):
    path = tmp_path / 'bad.yaml'
    path.write_text(text)
    with pytest.raises(ParameterFileError, match=f'^{path}: .*{message}'):
        read_blocks(path)


def test_a_missing_parameter_file_fails_the_static_check(sourced, tmp_path, write_spec):
    launch_file = tmp_path / 'missing.launch.py'
    launch_file.write_text(
        'from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n'
        'def generate_launch_description():\n    return LaunchDescription([Node(\n'
        "        package='my_robot_pkg', executable='sensor_publisher', name='s',\n"
        "        parameters=['/nonexistent/params.yaml'])])\n")
    report = check_static(load_spec(write_spec('')), launch_file)
    assert not report.ok
    assert '/nonexistent/params.yaml: cannot read the parameter file' in str(report)


@pytest.mark.parametrize(('value', 'name'), [
    (True, 'bool'), (3, 'integer'), (3.0, 'double'), ('x', 'string'), ([1, 2], 'integer_array'),
    ([1.0], 'double_array'), (['a'], 'string_array'), ([True], 'bool_array'),
    (b'\x01', 'byte_array'), ([1, 'a'], None),
])
def test_ros_types_of_python_values(value, name):
    assert ros_type(value) == name


def test_judging_values_type_first_then_value_then_range():
    double = ParameterSpec('rate', 'double', 2.0, True)
    assert judge(double, 2.0) is None
    assert judge(double, 2) == 'type integer (2), the spec says double'
    assert judge(double, 2.5) == 'value 2.5, the spec says 2.0'
    ranged = ParameterSpec('n', 'integer', min=1, max=3)
    assert judge(ranged, 3) is None
    assert judge(ranged, 0) == 'value 0 is below the minimum 1'
    assert judge(ParameterSpec('flag', 'integer'), True) == \
        'type bool (True), the spec says integer'
    assert judge(ParameterSpec('list', 'string_array', ['a'], True), ['a']) is None


@pytest.mark.parametrize('value', [['lidar'], ('lidar',)])
def test_an_array_reads_as_a_list_whatever_the_stack_gave(value):
    """Jazzy's launch_ros evaluates a list parameter to a tuple, the clean room to a
    list, rclpy may give an array.array: a report shows each as the spec's list."""
    assert show(value) == "['lidar']"
    assert show(array('d', [0.5])) == '[0.5]'
    assert judge(ParameterSpec('sensors', 'string_array', ['radar'], True), value) == \
        "value ['lidar'], the spec says ['radar']"
