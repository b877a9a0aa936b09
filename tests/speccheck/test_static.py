"""The static check: launch files of my_robot_pkg (and one test file) against specs,
every kind of requirement met and not met, without starting any node."""
from __future__ import annotations

import pytest
from speccheck import Status, check_static, load_spec

from tests.speccheck.conftest import LAUNCH_FILES

MET, FAILED, NOT_CHECKED = Status.MET, Status.FAILED, Status.NOT_CHECKED

SYSTEM = """\
nodes:
  /sensor_publisher: {package: my_robot_pkg, executable: sensor_publisher}
  /data_processor: {package: my_robot_pkg, executable: data_processor}
topics:
  /distance:
    publishers: [/sensor_publisher]
    subscribers: [/data_processor]
"""


def statuses(report, requirement):
    return [finding.status for finding in report.find(requirement)]


def exactly(report, requirement):
    return [f.status for f in report.findings if f.requirement == requirement]


def evidence(report, requirement):
    return ' | '.join(finding.evidence for finding in report.find(requirement))


def test_nodes_and_executables_met(installed, write_spec):
    report = check_static(load_spec(write_spec(SYSTEM)), installed('robot_system.launch.py'))
    report.assert_ok()
    assert statuses(report, 'node /sensor_publisher') == [MET]
    assert 'as my_robot_pkg/sensor_publisher' in evidence(report, 'node /sensor_publisher')
    assert statuses(report, 'executable of /data_processor') == [MET]
    # which topic names a program uses is only known when it runs
    assert statuses(report, 'topic /distance') == [NOT_CHECKED, NOT_CHECKED]
    assert "gives /distance if it uses the relative name 'distance'" in evidence(
        report, 'topic /distance: publisher')


def test_missing_and_unexpected_nodes_and_wrong_package_fail(installed, write_spec):
    spec = load_spec(write_spec(
        'nodes:\n  /sensor_publisher: {package: other_pkg}\n  /lidar: {}\n'))
    report = check_static(spec, installed('robot_system.launch.py'))
    assert not report.ok
    assert statuses(report, 'node /sensor_publisher') == [FAILED]
    assert "package 'my_robot_pkg', the spec says 'other_pkg'" in evidence(
        report, 'node /sensor_publisher')
    assert statuses(report, 'node /lidar') == [FAILED]
    assert 'would start: /sensor_publisher, /data_processor' in evidence(report, 'node /lidar')
    assert statuses(report, 'node /data_processor') == [FAILED]
    assert 'not in the spec' in evidence(report, 'node /data_processor')


def test_an_executable_that_is_not_installed_fails(installed, write_spec):
    report = check_static(load_spec(write_spec(SYSTEM)),
                          installed('mistake_executable_name.launch.py'))
    assert statuses(report, 'executable of /sensor_publisher') == [FAILED]
    missing = evidence(report, 'executable of /sensor_publisher')
    assert "package my_robot_pkg has no executable 'sensor_publisher.py'; it has: " in missing
    assert 'robot_controller, sensor_publisher' in missing
    assert statuses(report, 'node /sensor_publisher') == [FAILED]  # executable differs too
    assert statuses(report, 'executable of /data_processor') == [MET]


ARGUMENTS = """\
arguments:
  sim_mode: {default: 'true', choices: ['true', 'false']}
  controller: {default: auto, choices: [auto, manual]}
  sensor_rate: {default: 2.0}
"""


def test_declared_arguments_met(installed, write_spec):
    report = check_static(load_spec(write_spec(ARGUMENTS)),
                          installed('conditional_sensors.launch.py'))
    report.assert_ok()
    assert statuses(report, 'argument') == [MET, MET, MET]
    assert "default 'true', choices ['true', 'false']" in evidence(report, 'argument sim_mode')


def test_argument_defaults_choices_and_absence_fail(installed, write_spec):
    spec = load_spec(write_spec("""\
arguments:
  sim_mode: {default: 'false'}
  controller: {choices: [auto, manual, joystick]}
  use_filter: {required: true}
  robot_name: {}
"""))
    report = check_static(spec, installed('conditional_sensors.launch.py'))
    assert statuses(report, 'argument') == [FAILED] * 4
    assert "default 'true', the spec says 'false'" in evidence(report, 'argument sim_mode')
    assert "choices ['auto', 'manual'], the spec says ['auto', 'manual', 'joystick']" in \
        evidence(report, 'argument controller')
    assert 'the spec wants it required' in evidence(report, 'argument use_filter')
    assert 'not declared; the launch file declares: sim_mode, use_filter, controller' in \
        evidence(report, 'argument robot_name')


def test_an_argument_given_but_never_declared_fails(installed, write_spec):
    report = check_static(load_spec(write_spec('')), installed('robot_args.launch.py'),
                          {'robot_nme': 'x'})
    assert statuses(report, 'argument robot_nme') == [FAILED]
    assert 'given as robot_nme:=x but no launch file declares' in report.find(
        'argument robot_nme')[0].evidence


def test_conditions_follow_the_given_arguments(installed, write_spec):
    spec = load_spec(write_spec(
        'nodes:\n  /robot_controller: {package: my_robot_pkg, executable: robot_controller}\n'))
    started = check_static(spec, installed('conditional_sensors.launch.py'))
    assert statuses(started, 'node /robot_controller') == [NOT_CHECKED]  # no name= given
    assert 'without a name' in evidence(started, 'node /robot_controller')
    manual = check_static(spec, installed('conditional_sensors.launch.py'),
                          {'controller': 'manual'})
    assert statuses(manual, 'node /robot_controller') == [FAILED]
    assert 'because its condition is false' in evidence(manual, 'node /robot_controller')


def test_wiring_of_a_node_started_without_a_name(installed, write_spec):
    # the spec node is paired with the unnamed Node action, and its topics judged on it
    report = check_static(load_spec(write_spec(SYSTEM)),
                          installed('conditional_sensors.launch.py'))
    assert statuses(report, 'node /sensor_publisher') == [NOT_CHECKED]
    assert exactly(report, 'topic /distance: publisher /sensor_publisher') == [NOT_CHECKED]
    assert exactly(report, 'topic /distance: subscriber /data_processor') == [NOT_CHECKED]
    assert "if it uses the relative name 'distance'" in evidence(
        report, 'topic /distance: subscriber')
    assert 'starts no node of that name' not in evidence(report, 'topic /distance')


def test_parameter_types_values_and_ranges(installed, write_spec):
    spec = load_spec(write_spec("""\
nodes:
  /data_processor:
    executable: data_processor
    parameters:
      window_size: {type: integer, min: 1, max: 3}
  /sensor_publisher:
    executable: sensor_publisher
    parameters:
      publish_rate: {type: double, value: 5.0}
"""))
    good = check_static(spec, installed('conditional_sensors.launch.py'),
                        {'sensor_rate': '5.0'})
    # PythonExpression max(1, int(5.0)) = 5: above the range
    assert statuses(good, 'node /data_processor: parameter window_size') == [FAILED]
    assert 'value 5 is above the maximum 3' in evidence(good, 'node /data_processor: parameter')
    assert statuses(good, 'node /sensor_publisher: parameter publish_rate') == [MET]
    slow = check_static(spec, installed('conditional_sensors.launch.py'),
                        {'sensor_rate': '2.0'})
    assert statuses(slow, 'node /data_processor: parameter window_size') == [MET]
    assert 'value 2.0, the spec says 5.0' in evidence(slow, 'node /sensor_publisher: parameter')


def test_an_integer_for_a_double_parameter_fails(installed, write_spec):
    spec = load_spec(write_spec(
        'nodes:\n  /robot_controller:\n    parameters:\n'
        '      update_rate: {type: double, min: 1, max: 50}\n'))
    report = check_static(spec, installed('mistake_integer_rate.launch.py'))
    assert statuses(report, 'node /robot_controller: parameter update_rate') == [FAILED]
    assert 'type integer (2), the spec says double' in evidence(report, 'node /robot_controller')


def test_parameter_files_exact_and_wildcard_keys_later_sources_win(installed, write_spec):
    spec = load_spec(write_spec("""\
nodes:
  /sensor_publisher:
    parameters:
      publish_rate: {type: double, value: 1.0}
  /robot_controller:
    parameters:
      robot_name: {type: string, value: scout_2}
      update_rate: {type: double, value: 20.0}
      max_linear_speed: {type: double, value: 0.2}
      max_angular_speed: {type: double}
      enabled_sensors: {type: string_array, value: [lidar]}
      sensors.lidar.topic: {type: string, value: front_scan}
      sensors.lidar.enabled: {type: bool}
      sensors.lidar.range_max: {type: double}
      sensors.camera.enabled: {type: bool, value: false}
"""))
    report = check_static(spec, installed('layered_params.launch.py'))
    report.assert_ok()
    assert 'from slow_mode.yaml key /**' in evidence(
        report, 'node /robot_controller: parameter max_linear_speed')
    assert 'from robot_params.yaml key /robot_controller' in evidence(
        report, 'node /robot_controller: parameter update_rate')
    # publish_rate reaches the controller through /** too, but the node ignores it: no failure
    assert not report.find('node /robot_controller: parameter publish_rate')


def test_includes_pass_arguments_and_namespaces(installed, write_spec):
    spec = load_spec(write_spec("""\
nodes:
  /robot1/robot_controller:
    executable: robot_controller
    parameters: {robot_name: {type: string, value: alpha}}
  /robot2/robot_controller:
    executable: robot_controller
    parameters: {robot_name: {type: string, value: scout}}
"""))
    report = check_static(spec, installed('bringup_twice.launch.py'))
    assert statuses(report, 'node /robot1/robot_controller: parameter') == [MET]
    # launch configurations are not scoped by an include: robot2 gets robot1's name
    assert statuses(report, 'node /robot2/robot_controller: parameter') == [FAILED]
    assert "value 'alpha', the spec says 'scout'" in evidence(report, 'node /robot2/')


def test_a_launch_file_that_fails_is_reported_with_launch_s_message(installed, write_spec):
    report = check_static(load_spec(write_spec(SYSTEM)), installed('robot_instance.launch.py'))
    assert [f.status for f in report.findings] == [FAILED]
    assert ("Included launch description missing required argument 'robot_ns' "
            "(description: 'Namespace of this robot, e.g. robot1'), given: []") in \
        report.findings[0].evidence


@pytest.fixture
def scoped(sourced):
    spec = load_spec(LAUNCH_FILES / 'scoped.yaml')
    return lambda **arguments: check_static(spec, LAUNCH_FILES / 'scoped.launch.py', arguments)


def test_groups_namespaces_global_parameters_and_remaps(scoped):
    report = scoped()
    assert exactly(report, 'node /robot1/lidar') == [MET]
    assert statuses(report, 'node /robot1/filter: parameter use_sim_time') == [MET]
    assert 'SetParameter' in evidence(report, 'node /robot1/filter: parameter use_sim_time')
    # outside the group: no namespace, no use_sim_time
    assert exactly(report, 'node /controller') == [MET]
    assert not report.find('node /controller: parameter use_sim_time')


def test_topic_wiring_from_remaps(scoped):
    report = scoped()
    assert statuses(report, 'topic /robot1/scan') == [MET, MET]
    assert 'remap distance:=scan gives /robot1/scan' in evidence(report, 'topic /robot1/scan')
    assert statuses(report, 'topic /filtered: publisher /robot1/filter') == [MET]
    assert statuses(report, 'topic /scan: publisher /robot1/lidar') == [FAILED]
    assert 'remap distance:=scan gives /robot1/scan, not /scan' in evidence(report, 'topic /scan')


def test_a_misspelt_parameter_name_fails(scoped):
    report = scoped()
    assert statuses(report, 'node /controller: parameter max_linear_sped') == [FAILED]
    assert statuses(report, 'node /controller: parameter max_linear_speed') == [NOT_CHECKED]


def test_what_only_happens_at_run_time_is_not_checked_statically(scoped):
    unchecked = evidence(scoped(), 'launch file')
    for kind in ('OpaqueFunction', 'TimerAction', 'RegisterEventHandler'):
        assert f'{kind} in scoped.launch.py' in unchecked
    assert 'not checked statically' in unchecked
    assert '/late' not in unchecked  # the TimerAction's node is not guessed


def test_a_launch_argument_moves_the_group_and_a_missing_node_is_not_judged(scoped):
    """scoped.launch.py has an OpaqueFunction and a TimerAction: /robot1/lidar may come
    from one of them, so its absence among the visible nodes is not a failure."""
    report = scoped(robot='robot2')
    assert exactly(report, 'node /robot1/lidar') == [NOT_CHECKED]
    assert ('no Node action the static check can see starts it; an OpaqueFunction or '
            'TimerAction or RegisterEventHandler of the launch files may') in evidence(
        report, 'node /robot1/lidar')
    assert exactly(report, 'node /robot2/lidar') == [FAILED]  # unexpected: not in the spec


def test_a_node_missing_from_a_fully_visible_launch_file_fails(installed, write_spec):
    report = check_static(load_spec(write_spec('nodes:\n  /lidar: {}\n')),
                          installed('robot_system.launch.py'))
    assert exactly(report, 'node /lidar') == [FAILED]
    assert 'no Node action starts it; the launch file would start: ' in evidence(
        report, 'node /lidar')


def test_a_multi_segment_relative_name_is_named_whole(installed, write_spec):
    """turtlesim's turtle1/pose: relative names can have several segments."""
    spec = load_spec(write_spec(
        'nodes:\n  /sensor_publisher: {}\ntopics:\n  /robot/distance:\n'
        '    publishers: [/sensor_publisher]\n'))
    report = check_static(spec, installed('robot_system.launch.py'))
    assert "the program gives /robot/distance if it uses the relative name 'robot/distance'" \
        in evidence(report, 'topic /robot/distance: publisher')


def test_a_value_outside_the_declared_choices_fails_like_launch(installed, write_spec):
    report = check_static(load_spec(write_spec(ARGUMENTS)),
                          installed('conditional_sensors.launch.py'), {'controller': 'joystick'})
    [finding] = report.findings
    assert finding.status is FAILED
    assert ('Argument "controller" provided value "joystick" is not valid. Valid options are: '
            "['auto', 'manual']") in finding.evidence


OPAQUE_ONLY = """\
from launch import LaunchDescription
from launch.actions import OpaqueFunction


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=lambda context: [])])
"""
EMPTY = """\
from launch import LaunchDescription


def generate_launch_description():
    return LaunchDescription([])
"""


def test_starting_no_visible_node_is_never_met(write_spec, tmp_path):
    """'would start no nodes' is not a met requirement of a spec with nodes: not judged
    when a function may start them, failed when nothing could (7.2's draft)."""
    spec = load_spec(write_spec('nodes:\n  /lidar: {}\n'))
    for name, text, status in (('opaque.launch.py', OPAQUE_ONLY, NOT_CHECKED),
                               ('empty.launch.py', EMPTY, FAILED)):
        (tmp_path / name).write_text(text)
        report = check_static(spec, tmp_path / name)
        assert exactly(report, 'launch file')[0] is status, report
        assert exactly(report, 'node /lidar') == [status], report
