"""Lesson 6.7 (debugging a multi-node system): each of the four faults of
debug_demo_pkg's broken_system.launch.py is reproduced, and the tool output
the lesson uses to reveal it is asserted; the fixed system delivers every
sensor's readings; the log-level switches show what the lesson says.

The broken launch runs once for the module (its faults do not change while
it runs) and is stopped before the tests that start other launches (the
tests run in file order); every `ros2` command is retried until it shows the state asked
for, or the hang guard runs out and the assertion shows its last output.
"""
from __future__ import annotations

import re
import subprocess
from collections.abc import Callable, Iterator
from pathlib import Path

import labkit
import psutil
import pytest
from textbook import paths
from textbook.isolation import holding_fixed_domains

from .._polling import poll
from ._shown_snippets import launch_files_included_by

LESSON = paths.LESSONS / 'ch06/L1/07_debugging_multi_node_systems.md'
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
OTHER_DOMAIN = '101'  # the additional_env of the right sensor in broken_system.launch.py
SENSORS = ('/front_sensor', '/rear_sensor', '/left_sensor')  # visible in the launch's domain
TOPICS = ('/range/front', '/range/rear', '/range/left', '/range/right')


def _ros2(env: dict[str, str], *words: str, shows: Callable[[str], bool] = lambda _: True,
          ) -> str:
    """stdout+stderr of `ros2 WORDS`, run until `shows(output)` or the hang guard runs out."""
    outputs = []

    def run() -> bool:
        result = subprocess.run(['ros2', *words], env=env, cwd=paths.WORKSPACE,
                                capture_output=True, text=True, timeout=HANG_GUARD)
        outputs.append(result.stdout + result.stderr)
        return shows(outputs[-1])

    poll(run, HANG_GUARD)
    return outputs[-1]


@pytest.fixture(scope='module')
def broken(ros_env) -> Iterator[labkit.Background]:
    """broken_system.launch.py, up and past the monitor's first complaint; it holds
    domain 101 meanwhile (the lesson's run would otherwise see this sensor there)."""
    with holding_fixed_domains([int(OTHER_DOMAIN)]), \
            labkit.launch('debug_demo_pkg', 'broken_system.launch.py', env=ros_env,
                          cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(['/obstacle_monitor', *SENSORS], timeout=HANG_GUARD)
        run.wait_for_output(r'\[right_sensor\]: Publishing', timeout=HANG_GUARD)
        run.wait_for_output(r'No readings yet from', timeout=HANG_GUARD)
        yield run


@pytest.fixture
def quiet_domain(broken) -> None:
    """The broken system stopped: its best-effort /range/left and its monitor would
    otherwise meet the nodes of the next launch in the same domain."""
    broken.stop()


def _pid_of(run: labkit.Background, node: str) -> str:
    """The process ID the launch log gives the process that logs as `node`."""
    output = run.output()
    process = re.search(rf'^\[(\S+)\] .*\[{node}\]', output, re.M).group(1)
    return re.search(rf'\[{re.escape(process)}\]: process started with pid \[(\d+)\]',
                     output).group(1)


def _written(path: Path, text: str) -> str:
    """The file once it holds `text` (a node writes its log file in batches)."""
    poll(lambda: text in path.read_text(), HANG_GUARD)
    return path.read_text()


def test_symptom_the_monitor_hears_no_sensor(broken):
    output = broken.output()
    assert ('No readings yet from: /range/front, /range/rear, /range/left, /range/right'
            in output), output
    assert 'process has died' not in output, output
    assert len(re.findall(r'\]: process started with pid', output)) == 5, output


def test_fault4_node_runs_but_is_in_another_domain(broken, ros_env):
    output = broken.output()
    assert re.search(r'\[right_sensor\]: Publishing Float32 readings on \"/range/right\"',
                     output), output
    nodes = _ros2(ros_env, 'node', 'list',
                  shows=lambda out: all(node in out for node in SENSORS))
    # the fault: the right sensor runs but is not listed here (nodes of an earlier run
    # that reused this domain may still be announced for a while: not the point here)
    assert {'/obstacle_monitor', *SENSORS} <= set(nodes.split()), nodes
    assert '/right_sensor' not in nodes.split(), nodes
    pid = _pid_of(broken, 'right_sensor')
    environ = Path(f'/proc/{pid}/environ').read_bytes().split(b'\0')
    assert f'ROS_DOMAIN_ID={OTHER_DOMAIN}'.encode() in environ
    assert ros_env['ROS_DOMAIN_ID'] != OTHER_DOMAIN
    # ~/.ros/log keeps the files of earlier runs, and an old process may have had
    # this pid: only a file written since this process started is its own.
    started = psutil.Process(int(pid)).create_time()
    log_files = [path for path in Path('~/.ros/log').expanduser().glob(f'*_{pid}_*.log')
                 if path.stat().st_mtime >= started]
    assert len(log_files) == 1, log_files
    assert '[right_sensor]: Publishing' in _written(log_files[0], '[right_sensor]: Publishing')
    elsewhere = _ros2({**ros_env, 'ROS_DOMAIN_ID': OTHER_DOMAIN}, 'node', 'list',
                      shows=lambda out: '/right_sensor' in out)
    assert '/right_sensor' in elsewhere.split(), elsewhere


def test_fault1_topic_name_mismatch(broken, ros_env):
    topics = _ros2(ros_env, 'topic', 'list', '-t', shows=lambda out: '/range_front' in out)
    assert '/range_front [std_msgs/msg/Float32]' in topics.splitlines(), topics
    front = _ros2(ros_env, 'node', 'info', '/front_sensor',
                  shows=lambda out: '/range_front' in out)
    publishers = front.partition('Publishers:')[2].partition('Service Servers:')[0]
    assert '/range_front: std_msgs/msg/Float32' in publishers, front
    monitor = _ros2(ros_env, 'node', 'info', '/obstacle_monitor',
                    shows=lambda out: all(topic in out for topic in TOPICS))
    subscribers = monitor.partition('Subscribers:')[2].partition('Publishers:')[0]
    assert subscribers.split()[::2] == [f'{topic}:' for topic in sorted(TOPICS)], monitor
    echo = _ros2(ros_env, 'topic', 'echo', '/range/front', '--once', '--timeout', '2')
    assert 'data:' not in echo, echo


def _endpoints(info: str) -> list[tuple[str, str, str, str]]:
    """(endpoint type, node, message type, reliability) of each `topic info -v` block."""
    blocks = re.findall(r'Node name: (\S+)\n.*?Topic type: (\S+)\n.*?Endpoint type: (\S+)\n'
                        r'.*?Reliability: (\S+)\n', info, re.S)
    return sorted((kind, node, type_, reliability) for node, type_, kind, reliability in blocks)


def test_fault2_message_type_mismatch(broken, ros_env):
    topics = _ros2(ros_env, 'topic', 'list', '-t', shows=lambda out: 'Float64' in out)
    assert '/range/rear [std_msgs/msg/Float32, std_msgs/msg/Float64]' in topics.splitlines(), \
        topics
    info = _ros2(ros_env, 'topic', 'info', '-v', '/range/rear',
                 shows=lambda out: len(_endpoints(out)) == 2)
    assert _endpoints(info) == [
        ('PUBLISHER', 'rear_sensor', 'std_msgs/msg/Float64', 'RELIABLE'),
        ('SUBSCRIPTION', 'obstacle_monitor', 'std_msgs/msg/Float32', 'RELIABLE')], info
    as_published = _ros2(ros_env, 'topic', 'echo', '/range/rear', 'std_msgs/msg/Float64',
                         '--once')
    assert re.match(r'data: \d', as_published), as_published
    as_expected = _ros2(ros_env, 'topic', 'echo', '/range/rear', 'std_msgs/msg/Float32',
                        '--once', '--timeout', '2')
    assert 'data:' not in as_expected, as_expected


def test_fault3_qos_mismatch(broken, ros_env):
    assert re.search(r"\[obstacle_monitor\]: New publisher discovered on topic 'range/left', "
                     r"offering incompatible QoS\. No messages will be received from it\. "
                     r"Last incompatible policy: RELIABILITY", broken.output()), broken.output()
    info = _ros2(ros_env, 'topic', 'info', '-v', '/range/left',
                 shows=lambda out: len(_endpoints(out)) == 2)
    assert _endpoints(info) == [
        ('PUBLISHER', 'left_sensor', 'std_msgs/msg/Float32', 'BEST_EFFORT'),
        ('SUBSCRIPTION', 'obstacle_monitor', 'std_msgs/msg/Float32', 'RELIABLE')], info
    # The CLI adapts its QoS to the publisher: it receives what the monitor cannot.
    echo = _ros2(ros_env, 'topic', 'echo', '/range/left', '--once')
    assert re.match(r'data: \d', echo), echo


def test_doctor_reports_qos_and_lonely_topics(broken, ros_env):
    expected = ["QoS compatibility error found on topic '/range/left': "
                "Best effort publisher and reliable subscription;",
                'Subscriber without publisher detected on /range/front.',
                'Subscriber without publisher detected on /range/right.',
                'Publisher without subscriber detected on /range_front.']
    doctor = _ros2(ros_env, 'doctor', shows=lambda out: all(e in out for e in expected))
    for finding in expected:
        assert finding in doctor, doctor
    assert '1/3 check(s) failed' in doctor, doctor
    report = _ros2(ros_env, 'doctor', '--report',
                   shows=lambda out: '/range/left [std_msgs/msg/Float32]' in out)
    qos_list = report.partition('QOS COMPATIBILITY LIST')[2].partition('RMW MIDDLEWARE')[0]
    assert re.search(r'topic \[type\] +: /range/left \[std_msgs/msg/Float32\]\n'
                     r'publisher node +: left_sensor\nsubscriber node +: obstacle_monitor\n'
                     r'compatibility status +: ERROR: Best effort publisher and reliable '
                     r'subscription;', qos_list), report


def test_fixed_system_delivers_every_sensor(quiet_domain, ros_env):
    with labkit.launch('debug_demo_pkg', 'fixed_system.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(['/obstacle_monitor', *SENSORS, '/right_sensor'],
                           timeout=HANG_GUARD)
        run.wait_for_output(r'All 4 sensors report', timeout=HANG_GUARD)
        topics = _ros2(ros_env, 'topic', 'list', '-t',
                       shows=lambda out: all(topic in out for topic in TOPICS))
        doctor = _ros2(ros_env, 'doctor', shows=lambda out: 'All 3 checks passed' in out)
        exit_code = run.stop()
    output = run.output()
    first = sorted(re.findall(r'\[obstacle_monitor\]: First reading from "(\S+)"', output))
    assert first == sorted(TOPICS), output
    assert 'incompatible' not in output, output
    for topic in TOPICS:
        assert f'{topic} [std_msgs/msg/Float32]' in topics.splitlines(), topics
    assert '/range_front' not in topics, topics
    assert 'All 3 checks passed' in doctor, doctor
    assert exit_code == 0, output


def test_log_level_debug_for_the_whole_process(ros_env):
    sensor = labkit.run('debug_demo_pkg', 'range_sensor', '--ros-args', '--log-level', 'debug',
                        env=ros_env, cwd=paths.WORKSPACE)
    sensor.wait_for_output(r'Published reading #2', timeout=HANG_GUARD)
    sensor.stop()
    output = sensor.output()
    assert f"[rcl]: Using domain ID of '{ros_env['ROS_DOMAIN_ID']}'" in output, output


def test_log_level_for_one_logger(ros_env):
    sensor = labkit.run('debug_demo_pkg', 'range_sensor', '--ros-args', '--log-level',
                        'range_sensor:=debug', env=ros_env, cwd=paths.WORKSPACE)
    sensor.wait_for_output(r'Published reading #3', timeout=HANG_GUARD)
    sensor.stop()
    debug = [line for line in sensor.lines if line.startswith('[DEBUG]')]
    assert debug and all('[range_sensor]: Published reading #' in line for line in debug), \
        sensor.output()


def test_log_level_from_a_launch_file(quiet_domain, ros_env):
    with labkit.launch('debug_demo_pkg', 'monitor_debug.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as run:
        run.wait_for_output(r'\[DEBUG\] .*\[obstacle_monitor\]: front: ', timeout=HANG_GUARD)
        run.wait_for_output(r'\[DEBUG\] .*\[obstacle_monitor\]: rear: ', timeout=HANG_GUARD)
        run.wait_for_output(r'\[rear_sensor\]: Publishing', timeout=HANG_GUARD)
    debug = [line for line in run.lines if '[DEBUG]' in line]
    assert debug and all('[obstacle_monitor]' in line for line in debug), run.output()


def test_launch_debug_shows_the_traceback(ros_env):
    quiet = subprocess.run(['ros2', 'launch', 'my_robot_pkg', 'mistake_executable_name.launch.py'],
                           env=ros_env, cwd=paths.WORKSPACE, capture_output=True, text=True,
                           timeout=HANG_GUARD)
    loud = subprocess.run(['ros2', 'launch', '-d', 'my_robot_pkg',
                           'mistake_executable_name.launch.py'],
                          env=ros_env, cwd=paths.WORKSPACE, capture_output=True, text=True,
                          timeout=HANG_GUARD)
    quiet_output, loud_output = quiet.stdout + quiet.stderr, loud.stdout + loud.stderr
    assert 'Caught exception in launch (see debug for traceback)' in quiet_output, quiet_output
    assert 'Traceback' not in quiet_output, quiet_output
    assert 'Default logging verbosity is set to DEBUG' in loud_output, loud_output
    assert '[DEBUG] [launch]: Traceback (most recent call last):' in loud_output, loud_output
    assert quiet.returncode == loud.returncode == 1


def test_every_launch_file_the_lesson_shows_is_tested():
    tested = {('debug_demo_pkg', name) for name in
              ('broken_system.launch.py', 'fixed_system.launch.py', 'monitor_debug.launch.py')}
    tested.add(('ch06_solutions', 'ex67_fix_pipeline.launch.py'))  # tests/exercises
    shown = launch_files_included_by(LESSON)
    assert shown, f'{LESSON.name} shows no launch file'
    assert shown <= tested, f'launch files shown but not tested: {sorted(shown - tested)}'
