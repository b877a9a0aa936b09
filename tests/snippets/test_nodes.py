"""Every executable of every snippets package starts, joins the ROS graph, and
stops cleanly on Ctrl+C (SIGINT); the example robot's nodes do their job."""
from __future__ import annotations

import signal
import subprocess
import time
from pathlib import Path

import pytest
import rclpy
from rclpy.context import Context
from textbook import workspace

STARTUP_LIMIT = 30.0  # seconds; a hang guard, not a speed requirement
EXECUTABLES = [(package, exe) for package, exes in
               sorted(workspace.installed_executables(workspace.ensure_built()).items())
               for exe in exes]


def _start(ros_env, package: str, exe: str, *ros_args: str) -> subprocess.Popen:
    path = Path(workspace.INSTALL) / package / "lib" / package / exe
    return subprocess.Popen([str(path), "--ros-args", *ros_args], env=ros_env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def _stop(proc: subprocess.Popen) -> tuple[int, str]:
    proc.send_signal(signal.SIGINT)
    try:
        out, _ = proc.communicate(timeout=STARTUP_LIMIT)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
        pytest.fail(f"did not stop on SIGINT:\n{out}")
    return proc.returncode, out


@pytest.fixture
def graph():
    """An rclpy node in this test's domain, to look at the ROS graph."""
    context = Context()
    rclpy.init(context=context)
    node = rclpy.create_node("test_observer", context=context)
    yield node
    node.destroy_node()
    rclpy.shutdown(context=context)


def _wait_for_node(graph, name: str, proc: subprocess.Popen) -> bool:
    deadline = time.monotonic() + STARTUP_LIMIT
    while time.monotonic() < deadline and proc.poll() is None:
        if name in graph.get_node_names():
            return True
        time.sleep(0.2)
    return False


def test_there_are_executables():
    assert EXECUTABLES, "no executables installed from snippets/"


@pytest.mark.parametrize("package,exe", EXECUTABLES, ids=lambda v: v)
def test_node_starts_and_stops_cleanly(package, exe, ros_env, graph):
    probe = f"probe_{exe}"
    proc = _start(ros_env, package, exe, "-r", f"__node:={probe}")
    appeared = _wait_for_node(graph, probe, proc)
    code, out = _stop(proc)
    assert appeared, f"{package}/{exe} never appeared on the ROS graph:\n{out}"
    assert code == 0, f"{package}/{exe} exited with {code} on SIGINT:\n{out}"
    assert "Traceback" not in out, out


def _run_together(ros_env, *commands, seconds: float = 3.0) -> list[str]:
    procs = [_start(ros_env, *command) for command in commands]
    time.sleep(seconds)
    results = [_stop(proc) for proc in procs]
    assert [code for code, _ in results] == [0] * len(procs), results
    return [out for _, out in results]


def test_processor_receives_what_the_sensor_publishes(ros_env):
    processor, sensor = _run_together(
        ros_env, ("my_robot_pkg", "data_processor"),
        ("my_robot_pkg", "sensor_publisher", "-p", "publish_rate:=10.0"))
    published = [line.split(": Reading #")[1].split(": ")[1] for line in sensor.splitlines()
                 if ": Reading #" in line]
    received = [line.split("Received ")[1].split(" ->")[0] for line in processor.splitlines()
                if "Received " in line]
    assert published and received, (sensor, processor)
    # Discovery may drop the first readings and shutdown the last ones; the
    # rest arrive complete and in order.
    n = len(received)
    assert any(published[i:i + n] == received for i in range(len(published) - n + 1)), \
        (published, received)


def test_controller_reads_typed_and_nested_parameters_from_yaml(ros_env, ws_install):
    params = ws_install / "my_robot_pkg/share/my_robot_pkg/config/robot_params.yaml"
    (out,) = _run_together(
        ros_env, ("my_robot_pkg", "robot_controller", "--params-file", str(params)),
        seconds=1.5)
    assert 'Robot "scout" starting with update_rate=20.0 Hz' in out
    assert "Speed limits: linear 0.8 m/s, angular 1.5 rad/s" in out
    assert "Enabled sensors: lidar" in out
    assert "sensors.lidar: enabled=True, topic=front_scan, range_max=8.0" in out


def test_controller_rejects_a_parameter_of_the_wrong_type(ros_env):
    proc = _start(ros_env, "my_robot_pkg", "robot_controller", "-p", "update_rate:=fast")
    out, _ = proc.communicate(timeout=STARTUP_LIMIT)
    assert proc.returncode != 0
    assert "update_rate" in out
