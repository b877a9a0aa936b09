"""Every executable of every snippets package starts, joins the ROS graph, and
stops cleanly on Ctrl+C (SIGINT); the example robot's nodes do their job."""
from __future__ import annotations

import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest
import rclpy
from rclpy.context import Context
from speccheck.graph import read_parameters
from speccheck.ros_error import RosError
from textbook import workspace

from .._hang_evidence import native_stacks, tail, write_report
from .._polling import poll

STARTUP_LIMIT = 30.0  # seconds; a hang guard, not a speed requirement
EXECUTABLES = [(package, exe) for package, exes in
               sorted(workspace.installed_executables(workspace.ensure_built()).items())
               for exe in exes]


class NodeProcess:
    """A node started from the install tree, its output collected line by line."""

    def __init__(self, ros_env, package: str, exe: str, *ros_args: str):
        path = Path(workspace.INSTALL) / package / 'lib' / package / exe
        # faulthandler: a node that ignores Ctrl+C prints its Python stacks on SIGABRT
        self.proc = subprocess.Popen([str(path), '--ros-args', *ros_args],
                                     env={**ros_env, 'PYTHONFAULTHANDLER': '1'},
                                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                     text=True)
        self.exe = exe
        self.lines: list[str] = []
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        for line in self.proc.stdout:
            self.lines.append(line.rstrip('\n'))

    @property
    def output(self) -> str:
        return '\n'.join(self.lines)

    def wait_until(self, condition) -> bool:
        """Wait (up to the hang guard) until ``condition(lines)`` holds."""
        poll(lambda: condition(self.lines), STARTUP_LIMIT,
             stop=lambda: self.proc.poll() is not None)
        return condition(self.lines)

    def stop(self) -> int:
        """Ctrl+C, then the exit code (fails the test if the node does not stop, naming
        the file that keeps its native and Python stacks)."""
        self.proc.send_signal(signal.SIGINT)
        try:
            self.proc.wait(timeout=STARTUP_LIMIT)
        except subprocess.TimeoutExpired:
            native = native_stacks(self.proc.pid)
            self.proc.send_signal(signal.SIGABRT)
            try:
                self.proc.wait(timeout=STARTUP_LIMIT)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
            self._reader.join(timeout=STARTUP_LIMIT)
            report = write_report(f'node-{self.exe}', self.proc.pid, {
                'output, with the Python stacks (end)': tail(self.output, 200),
                'native stacks of every thread (gdb)': native})
            pytest.fail(f'did not stop on SIGINT within {STARTUP_LIMIT:g} s; its stacks are '
                        f'in {report}:\n{tail(self.output, 30)}')
        self._reader.join(timeout=STARTUP_LIMIT)
        return self.proc.returncode


def count(text: str):
    return lambda lines: sum(text in line for line in lines)


@pytest.fixture
def graph():
    """An rclpy node in this test's domain, to look at the ROS graph."""
    context = Context()
    rclpy.init(context=context)
    node = rclpy.create_node('test_observer', context=context)
    yield node
    node.destroy_node()
    rclpy.shutdown(context=context)


def _wait_for_node(graph, name: str, proc: subprocess.Popen) -> bool:
    return poll(lambda: name in graph.get_node_names(), STARTUP_LIMIT,
                stop=lambda: proc.poll() is not None)


def _answers(name: str) -> bool:
    """Whether node `name` answers on its parameter service, i.e. it spins.

    On the graph is not yet up: a node is listed once it exists, before its
    constructor has finished and it spins.  A Ctrl+C in that window stops it with
    rclpy's RCLError ("the given context is not valid"), as it does Jazzy's demo
    nodes, which are written the same way; this test is about a running node.
    """
    try:
        read_parameters(name, timeout=1.0)
    except RosError:
        return False
    return True


def _wait_until_spinning(name: str, proc: subprocess.Popen) -> bool:
    return poll(lambda: _answers(name), STARTUP_LIMIT, stop=lambda: proc.poll() is not None)


def test_there_are_executables():
    assert EXECUTABLES, 'no executables installed from snippets/'


#: What an executable needs to start at all, as its launch file gives it, or to
#: stay up until it is stopped.
REQUIRED_ARGUMENTS = {
    ('capstone_robot', 'spawner'): ('-p', 'turtle_name:=probe_turtle'),  # else it refuses
    # Without a turtlesim it ends by itself after startup_timeout (10 s).
    ('capstone_robot', 'sim_watchdog'): ('-p', f'startup_timeout:={10 * STARTUP_LIMIT}'),
}


@pytest.mark.parametrize('package,exe', EXECUTABLES, ids=lambda v: v)
def test_node_starts_and_stops_cleanly(package, exe, ros_env, graph):
    probe = f'probe_{exe}'
    node = NodeProcess(ros_env, package, exe, '-r', f'__node:={probe}',
                       *REQUIRED_ARGUMENTS.get((package, exe), ()))
    appeared = _wait_for_node(graph, probe, node.proc)
    spinning = appeared and _wait_until_spinning(f'/{probe}', node.proc)
    code = node.stop()
    assert appeared, f'{package}/{exe} never appeared on the ROS graph:\n{node.output}'
    assert spinning, f'{package}/{exe} never answered on its parameter service:\n{node.output}'
    assert code == 0, f'{package}/{exe} exited with {code} on SIGINT:\n{node.output}'
    assert 'Traceback' not in node.output, node.output


def test_processor_receives_what_the_sensor_publishes(ros_env):
    processor = NodeProcess(ros_env, 'my_robot_pkg', 'data_processor')
    sensor = NodeProcess(ros_env, 'my_robot_pkg', 'sensor_publisher',
                         '-p', 'publish_rate:=10.0')
    got_five = processor.wait_until(lambda lines: count('Received ')(lines) >= 5)
    assert [sensor.stop(), processor.stop()] == [0, 0]
    assert got_five, (sensor.output, processor.output)
    published = [line.split(': Reading #')[1].split(': ')[1] for line in sensor.lines
                 if ': Reading #' in line]
    received = [line.split('Received ')[1].split(' ->')[0] for line in processor.lines
                if 'Received ' in line]
    # Discovery may drop the first readings and shutdown the last ones (the
    # sensor logs a reading before publishing it); the rest arrive complete
    # and in order.
    n = len(received)
    assert any(published[i:i + n] == received for i in range(len(published) - n + 1)), \
        (published, received)


def test_controller_reads_typed_and_nested_parameters_from_yaml(ros_env, ws_install):
    params = ws_install / 'my_robot_pkg/share/my_robot_pkg/config/robot_params.yaml'
    controller = NodeProcess(ros_env, 'my_robot_pkg', 'robot_controller',
                             '--params-file', str(params))
    configured = controller.wait_until(count('sensors.camera:'))
    assert controller.stop() == 0, controller.output
    assert configured, controller.output
    out = controller.output
    assert 'Robot "scout" starting with update_rate=20.0 Hz' in out
    assert 'Speed limits: linear 0.8 m/s, angular 1.5 rad/s' in out
    assert 'Enabled sensors: lidar' in out
    assert 'sensors.lidar: enabled=True, topic=front_scan, range_max=8.0' in out


def test_controller_rejects_a_parameter_of_the_wrong_type(ros_env):
    controller = NodeProcess(ros_env, 'my_robot_pkg', 'robot_controller',
                             '-p', 'update_rate:=fast')
    controller.proc.wait(timeout=STARTUP_LIMIT)
    controller._reader.join(timeout=STARTUP_LIMIT)
    assert controller.proc.returncode != 0
    assert 'update_rate' in controller.output


@pytest.mark.parametrize('world_args, world', [
    ((), '/turtlesim'),
    (('-p', 'world_node:=/base_driver'), '/base_driver'),
], ids=['turtlesim', 'a real robot driver'])
def test_sim_watchdog_without_a_turtlesim_exits_with_an_error(ros_env, world_args, world):
    """No world node (/turtlesim, or on a real robot the driver its world_node names)
    within startup_timeout: one clear line and exit code 1, which capstone.launch.py's
    sim:=false handler turns into a shutdown."""
    watchdog = NodeProcess(ros_env, 'capstone_robot', 'sim_watchdog',
                           '-p', 'startup_timeout:=1.0', *world_args)
    try:
        code = watchdog.proc.wait(timeout=STARTUP_LIMIT)
    finally:
        if watchdog.proc.poll() is None:
            watchdog.stop()
    watchdog._reader.join(timeout=STARTUP_LIMIT)
    assert code == 1, watchdog.output
    assert (f'[sim_watchdog]: {world} not found within 1.0 s: start the simulator first, '
            'or use sim:=true') in watchdog.output, watchdog.output
    assert 'Traceback' not in watchdog.output, watchdog.output


STOPPED_WHILE_STARTING = """
import sys
import rclpy
from capstone_robot.running import run

def make_node():
    node = rclpy.create_node('starting')
    rclpy.shutdown()  # what rclpy's Ctrl+C handler does when the signal comes now
    node.create_timer(0.1, lambda: None)  # the next step of starting fails
    return node

sys.exit(run(make_node))
"""

BROKEN_WHILE_STARTING = """
import sys
from capstone_robot.running import run

def make_node():
    raise RuntimeError('a real bug while starting')

sys.exit(run(make_node))
"""


@pytest.mark.parametrize('program, code, shown', [
    (STOPPED_WHILE_STARTING, 0, ''),
    (BROKEN_WHILE_STARTING, 1, 'RuntimeError: a real bug while starting'),
], ids=['stopped while starting', 'a real error while starting'])
def test_a_capstone_node_stopped_while_it_starts_exits_cleanly(ros_env, program, code, shown):
    """A launch may stop a node before it has finished starting (CI saw pose_estimator
    exit 1 that way when a fault test killed the safety monitor early); that is a
    stop on purpose and exits 0, while a real error still exits 1 with its traceback."""
    result = subprocess.run([sys.executable, '-c', program], env=ros_env, text=True,
                            capture_output=True, timeout=STARTUP_LIMIT, check=False)
    assert result.returncode == code, result.stdout + result.stderr
    assert shown in result.stderr
    if code == 0:
        assert 'Traceback' not in result.stderr, result.stderr


def test_spawner_without_a_turtle_name_refuses_with_exit_code_1(ros_env):
    """In the root namespace there is no name to take, so it must say so and stop."""
    spawner = NodeProcess(ros_env, 'capstone_robot', 'spawner')
    try:
        code = spawner.proc.wait(timeout=STARTUP_LIMIT)
    finally:
        spawner.proc.kill()
    spawner._reader.join(timeout=STARTUP_LIMIT)
    assert code == 1, spawner.output
    assert 'No turtle name: set turtle_name or start me in a namespace' in spawner.output
    assert 'Traceback' not in spawner.output, spawner.output
