"""The capstone robot system (chapter 7): every launch file of capstone_bringup
started as a student starts it, and the system doing its job.

Each test starts ``ros2 launch capstone_bringup ...`` through labkit, waits
for states (nodes in the graph, log lines, poses), never for a time, and
stops the launch as Ctrl+C does.  Checked: nodes and namespaces, the topic
wiring of each robot, the two layers of parameters, turtles that really
move, the service that holds a robot, the lifecycle node reaching
``active``, the safety monitor stopping a turtle before a wall, respawn of
the wall sensor, the shutdown when the safety monitor dies, ``sim:=false``
driving a turtlesim started elsewhere and shutting down when it ends, and a
bad ``robot_count`` refused.
"""
from __future__ import annotations

import math
import os
import re
import signal
from collections.abc import Iterator
from pathlib import Path

import labkit
import pytest
from labkit.grading.capstone import ROBOT_NODES, robot_nodes
from lifecycle_msgs.srv import GetState
from textbook import paths, workspace

from .._polling import wait_for
from ._launch_log import ENDED, STARTED
from ._turtlesim_client import SimClient, load_interfaces, load_turtlesim_interfaces
from ._wiring import Wiring, settled_graph, wiring_of

INSTALL = workspace.ensure_built()
if (INSTALL / 'turtlesim/share/turtlesim/HEADLESS').is_file():  # else a real one is installed
    load_turtlesim_interfaces(INSTALL)


load_interfaces(INSTALL, 'capstone_interfaces')

from capstone_interfaces.srv import SetMode  # noqa: E402
from turtlesim.msg import Pose  # noqa: E402

PACKAGE = 'capstone_bringup'
LAUNCH = paths.SNIPPETS / PACKAGE / 'launch'
HANG_GUARD = 60.0  # seconds; only stops a broken test from hanging, never a speed limit
WORLD = 11.088889  # metres, turtlesim's square


def robot_wiring(robot: str) -> Wiring:
    """The topics of one robot: who publishes, who subscribes (robot.launch.py's docstring)."""
    ns = f'/{robot}'
    return {
        f'{ns}/pose': (('/turtlesim',), (f'{ns}/pose_estimator', f'{ns}/wall_sensor')),
        f'{ns}/color_sensor': (('/turtlesim',), ()),
        f'{ns}/wall_reading': ((f'{ns}/wall_sensor',), (f'{ns}/safety_monitor',)),
        f'{ns}/estimated_pose': ((f'{ns}/pose_estimator',),
                                 (f'{ns}/controller', f'{ns}/patrol_planner')),
        f'{ns}/goal': ((f'{ns}/patrol_planner',), (f'{ns}/controller',)),
        f'{ns}/cmd_vel_nav': ((f'{ns}/controller',), (f'{ns}/safety_monitor',)),
        f'{ns}/cmd_vel': ((f'{ns}/safety_monitor',), ('/turtlesim',)),
        f'{ns}/safety_stop': ((f'{ns}/safety_monitor',), (f'{ns}/mission_recorder',)),
        f'{ns}/status': ((f'{ns}/patrol_planner',), (f'{ns}/mission_recorder',)),
    }


def _start(launch_file: str, ros_env: dict[str, str], **arguments: str) -> labkit.Background:
    return labkit.launch(PACKAGE, launch_file, launch_arguments=arguments, env=ros_env,
                         cwd=paths.WORKSPACE)


def _pid(run: labkit.Background, process: str) -> int:
    """The pid of the first start of ``process`` (e.g. 'safety_monitor')."""
    line = run.wait_for_output(rf'\[{process}-\d+\]: process started with pid', HANG_GUARD)
    return int(re.search(r'pid \[(\d+)\]', line).group(1))


def _next_line(run: labkit.Background, pattern: str, after: int) -> int:
    """The index of the first line after line ``after`` that matches ``pattern``."""
    regex = re.compile(pattern)
    return wait_for(lambda: next((index for index, line in enumerate(run.lines)
                                  if index > after and regex.search(line)), None),
                    HANG_GUARD, f'a line matching {pattern!r} after line {after}')


def _node_log(robot: str, node: str, text: str) -> str:
    """A pattern for a node's own log line, ``[turtle1.safety_monitor]: text``."""
    return rf'\[{robot}\.{node}\]: {re.escape(text)}'


def _stop_cleanly(run: labkit.Background) -> str:
    """Ctrl+C; every process must finish cleanly and the launch exit 0."""
    still_running = run.running
    code = run.stop()
    output = run.output()
    assert still_running, output
    assert 'process has died' not in output and 'Traceback' not in output, output
    started = [m.group(1) for line in output.splitlines() if (m := STARTED.match(line))]
    ended = [m.group(1) for line in output.splitlines() if (m := ENDED.match(line))]
    assert code == 0 and sorted(ended) == sorted(started), output
    return output


@pytest.fixture
def client() -> Iterator[SimClient]:
    ros = SimClient()
    yield ros
    ros.close()


def _moved(client: SimClient, robot: str, start: Pose | None = None) -> Pose:
    """Wait until ``robot``'s turtle is half a metre away from where it first was."""
    topic = f'/{robot}/pose'
    if topic not in client.latest:
        client.watch(Pose, topic)
    first = start or client.wait_for(topic, lambda pose: True, 'a first pose')
    return client.wait_for(
        topic, lambda pose: math.dist((pose.x, pose.y), (first.x, first.y)) > 0.5,
        f'{robot} moving half a metre from ({first.x:.2f}, {first.y:.2f})')


def _lifecycle_state(client: SimClient, node: str) -> str:
    return client.call(GetState, f'{node}/get_state').current_state.label


def test_capstone_starts_two_robots_that_patrol(ros_env, client):
    """Default capstone: turtlesim, turtle2 spawned, two robots wired, layered
    parameters, both turtles moving, recorders active, set_mode holds a robot."""
    robots = ('turtle1', 'turtle2')
    expected_nodes = ['/turtlesim', *(n for robot in robots for n in robot_nodes(robot))]
    expected: Wiring = {}
    for robot in robots:
        expected.update(robot_wiring(robot))
    with _start('capstone.launch.py', ros_env) as run:
        run.wait_for_nodes(expected_nodes, timeout=HANG_GUARD)
        run.wait_for_output(r'\[spawner-\d+\]: process has finished cleanly', HANG_GUARD)
        for robot in robots:  # the recorder subscribes only once it is active
            run.wait_for_output(_node_log(robot, 'mission_recorder',
                                          'Active: recording the mission'), HANG_GUARD)
        # Other topics are left out: the launch's own node (/launch_ros_<pid>)
        # listens to each recorder's transition_event.
        snapshot = settled_graph(expected, HANG_GUARD, only_expected=True)
        params = {node: labkit.read_parameters(node) for node in (
            '/turtle1/controller', '/turtle2/controller', '/turtle1/patrol_planner',
            '/turtle2/patrol_planner', '/turtle2/wall_sensor', '/turtle1/safety_monitor')}
        states = [_lifecycle_state(client, f'/{robot}/mission_recorder') for robot in robots]
        for robot in robots:
            _moved(client, robot)
        refused = client.call(SetMode, '/turtle1/set_mode', mode='dance')
        held = client.call(SetMode, '/turtle1/set_mode', mode='hold')
        still = client.wait_for('/turtle1/pose', lambda pose: pose.linear_velocity == 0.0
                                and pose.angular_velocity == 0.0, 'turtle1 standing still')
        _moved(client, 'turtle2', client.latest['/turtle2/pose'])  # turtle2 is not held
        held_still = client.latest['/turtle1/pose']  # ... while turtle1 stayed put
        output = _stop_cleanly(run)
    assert 'Spawned turtle2 at (2.00, 9.00)' in output, output
    # Beside the system: the launch's own node and this test's client.
    system = [node for node in snapshot.nodes
              if not node.startswith('/launch_ros_') and node != '/turtlesim_test_client']
    assert sorted(system) == sorted(expected_nodes), str(snapshot)
    assert wiring_of(snapshot, expected, only_expected=True) == expected, str(snapshot)
    for robot in robots:  # a lifecycle node publishes its transitions; launch listens
        assert snapshot.publishers(f'/{robot}/mission_recorder/transition_event') == (
            f'/{robot}/mission_recorder',), str(snapshot)
    # Layer 1 (defaults.yaml) and layer 2 (config/<robot>.yaml, which wins).
    assert params['/turtle1/controller']['max_linear'] == 1.0
    assert params['/turtle2/controller']['max_linear'] == 1.5
    assert params['/turtle2/controller']['k_angular'] == 4.0
    assert params['/turtle1/patrol_planner']['waypoints'] == [3.0, 3.0, 8.0, 3.0,
                                                              8.0, 8.0, 3.0, 8.0]
    assert params['/turtle2/patrol_planner']['waypoints'] == [5.5, 9.5, 9.5, 5.5,
                                                              5.5, 1.5, 1.5, 5.5]
    assert params['/turtle2/wall_sensor']['noise_stddev'] == 0.01  # code default: 0.0
    assert params['/turtle1/safety_monitor']['stop_distance'] == 0.8
    assert states == ['active', 'active']
    assert 'Mission recorder of turtle1 configured: activating' in output
    assert (refused.accepted, held.accepted) == (False, True), (refused, held)
    assert 'unknown mode' in refused.message and held.message == 'mode is now hold'
    assert math.dist((still.x, still.y), (held_still.x, held_still.y)) < 0.2, (still, held_still)


def test_safety_monitor_stops_the_turtle_before_the_wall(ros_env, client, tmp_path):
    """sim.launch.py and robot.launch.py started apart; a waypoint beyond the right
    wall drives turtle1 straight at it, and the safety monitor stops it in time."""
    beyond_the_wall = tmp_path / 'wall.yaml'
    beyond_the_wall.write_text('/**/patrol_planner:\n  ros__parameters:\n'
                               '    waypoints: [12.0, 5.544445]\n')
    with _start('sim.launch.py', ros_env) as sim, \
            _start('robot.launch.py', ros_env, robot_params=str(beyond_the_wall)) as robot:
        robot.wait_for_nodes(['/turtlesim', *robot_nodes('turtle1')], timeout=HANG_GUARD)
        robot.wait_for_output(_node_log('turtle1', 'safety_monitor', 'Safety stop: wall'),
                              HANG_GUARD)
        client.watch(Pose, '/turtle1/pose')
        stopped = client.wait_for('/turtle1/pose', lambda pose: pose.linear_velocity == 0.0,
                                  'turtle1 stopped')
        robot.wait_for_output(_node_log('turtle1', 'mission_recorder',
                                        'safety_stop: stop 1'), HANG_GUARD)
        waypoints = labkit.read_parameters('/turtle1/patrol_planner')['waypoints']
        robot_output = _stop_cleanly(robot)
        sim_output = _stop_cleanly(sim)
    assert waypoints == [12.0, 5.544445]  # the file given on the command line was used
    assert WORLD - 0.8 - 0.5 < stopped.x < WORLD - 0.3, (stopped, robot_output)
    assert abs(stopped.theta) < 0.1, stopped  # it drove straight at the wall
    assert 'I hit the wall' not in sim_output, sim_output
    assert '[turtlesim_node-1]: process started' in sim_output
    assert 'spawner' not in sim_output  # robot_count 1: turtlesim's own turtle1 only


def test_respawn_and_shutdown_when_the_safety_monitor_dies(ros_env):
    """The wall sensor is restarted when it dies (the safety monitor holds the
    robot meanwhile); the safety monitor's death ends the whole launch."""
    with _start('capstone.launch.py', ros_env, robot_count='1') as run:
        run.wait_for_nodes(['/turtlesim', *robot_nodes('turtle1')], timeout=HANG_GUARD)
        run.wait_for_output(_node_log('turtle1', 'mission_recorder', 'Active'), HANG_GUARD)
        # A waypoint reached: the monitor has readings and passes commands. Before
        # that it may still hold its start-up stop, and a kill would log no new one.
        run.wait_for_output(_node_log('turtle1', 'patrol_planner', 'Waypoint reached'),
                            HANG_GUARD)
        sensor = _pid(run, 'wall_sensor')
        killed_at = len(run.lines) - 1
        os.kill(sensor, signal.SIGKILL)
        # Lines after the kill only: the same lines also come at start-up.
        restart = _next_line(run, r'\[wall_sensor-\d+\]: process started with pid', killed_at)
        respawned = int(re.search(r'pid \[(\d+)\]', run.lines[restart]).group(1))
        _next_line(run, _node_log('turtle1', 'safety_monitor',
                                  'Safety stop: no wall reading for 1.0 s'), killed_at)
        ready = _next_line(run, _node_log('turtle1', 'wall_sensor', 'Measuring walls'), restart)
        _next_line(run, _node_log('turtle1', 'safety_monitor', 'Clear'), ready)
        os.kill(_pid(run, 'safety_monitor'), signal.SIGKILL)
        wait_for(lambda: not run.running, HANG_GUARD, 'the launch to end by itself')
        code = run.returncode
    output = run.output()
    assert respawned != sensor
    assert code == 0, output  # a shutdown asked for is a normal end
    assert 'The safety monitor of turtle1 exited: shutting down' in output, output
    assert 'Capstone shutting down: the safety monitor of turtle1 exited' in output, output
    died = [line for line in output.splitlines() if 'process has died' in line]
    assert len(died) == 2 and all('exit code -9' in line for line in died), output
    started = [m.group(1) for line in output.splitlines() if (m := STARTED.match(line))]
    ended = [m.group(1) for line in output.splitlines() if (m := ENDED.match(line))]
    # Everything else finished cleanly: the respawned sensor and all other nodes.
    assert sorted(ended + ['wall_sensor', 'safety_monitor']) == sorted(started), output


def test_sim_false_drives_a_turtlesim_started_elsewhere(ros_env, client):
    """sim:=false starts no simulator and no spawner: the robot drives the turtle
    of a turtlesim started by hand."""
    with labkit.run('turtlesim', 'turtlesim_node', env=ros_env) as turtlesim:
        turtlesim.wait_for_nodes(['/turtlesim'], timeout=HANG_GUARD)
        client.watch(Pose, '/turtle1/pose')
        start = client.wait_for('/turtle1/pose', lambda pose: True, 'a first pose')
        with _start('capstone.launch.py', ros_env, sim='false', robot_count='1') as run:
            run.wait_for_nodes(robot_nodes('turtle1'), timeout=HANG_GUARD)
            _moved(client, 'turtle1', start)
            nodes = labkit.graph().nodes
            output = _stop_cleanly(run)
        turtlesim.stop()
    assert 'turtlesim_node' not in output and 'spawner' not in output, output
    assert [node for node in nodes if node.endswith('turtlesim')] == ['/turtlesim']
    started = [m.group(1) for line in output.splitlines() if (m := STARTED.match(line))]
    assert sorted(started) == sorted([*ROBOT_NODES, 'sim_watchdog']), output


# R7 with sim:=false (the watchdog sees a separately started turtlesim leave and the
# launch shuts down) is tested once, as lesson 7.2 shows it:
# test_ch07_lesson_72.test_sim_false_the_books_file_shuts_down_without_turtlesim.


@pytest.mark.parametrize('launch_file', ['capstone.launch.py', 'sim.launch.py'])
def test_a_robot_count_without_a_config_file_is_refused(ros_env, launch_file):
    with _start(launch_file, ros_env, robot_count='5') as run:
        wait_for(lambda: not run.running, HANG_GUARD, 'the launch to refuse robot_count:=5')
    output = run.output()
    assert run.returncode == 1, output
    assert 'process started' not in output, output
    assert ("Caught exception in launch (see debug for traceback): robot_count must be a "
            "whole number from 1 to 4, got '5'") in output, output


def test_every_capstone_launch_file_is_tested():
    # capstone_draft.launch.py, the assistant's draft, is launched by test_ch07_lesson_72.
    tested = {'capstone.launch.py', 'sim.launch.py', 'robot.launch.py',
              'capstone_draft.launch.py'}
    assert {path.name for path in LAUNCH.glob('*.launch.*')} == tested


def test_every_robot_count_has_its_config_file():
    config = paths.SNIPPETS / PACKAGE / 'config'
    robots = sorted(path.stem for path in Path(config).glob('turtle*.yaml'))
    assert robots == [f'turtle{n}' for n in range(1, 5)], robots
