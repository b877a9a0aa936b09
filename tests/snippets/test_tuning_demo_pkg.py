"""tuning_demo_pkg (lesson 6.10): the wasteful baseline pipeline launches and
runs its four nodes in four processes, and the labkit measurements the lesson
relies on read it correctly: rates near what the nodes are configured to,
message sizes equal to the image's pixels plus the serialized header,
CPU and memory of exactly the launch's processes.

Expected values come from the running nodes' parameters and from
serializing messages here, never from numbers written into the test.
"""
from __future__ import annotations

import re
from collections.abc import Iterator

import labkit
import psutil
import pytest
from labkit.processes import process_usage
from labkit.rates import measure_rates
from rclpy.serialization import serialize_message
from sensor_msgs.msg import Image
from std_msgs.msg import Float32
from textbook import paths

HANG_GUARD = 60.0  # seconds; only stops a broken test from hanging, never a speed limit
NODES = ('/camera', '/detector', '/image_stats', '/monitor')
WINDOW = 5.0  # seconds of measurement
CHANNELS = {'rgb8': 3}


@pytest.fixture(scope='module')
def baseline(ros_env) -> Iterator[labkit.Background]:
    """pipeline_baseline.launch.py, up until the monitor has counted detections."""
    with labkit.launch('tuning_demo_pkg', 'pipeline_baseline.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(NODES, timeout=HANG_GUARD)
        run.wait_for_output(r'\[monitor\]: [1-9]\d* detections in the last second',
                            timeout=HANG_GUARD)
        yield run


@pytest.fixture(scope='module')
def camera(baseline) -> dict:
    return labkit.read_parameters('/camera')


def _started_pids(run: labkit.Background) -> dict[str, int]:
    """Node process name (camera-1 -> camera) -> pid, from the launch's own log lines."""
    return {name: int(pid) for name, pid in
            re.findall(r'\[INFO\] \[(\w+)-\d+\]: process started with pid \[(\d+)\]',
                       run.output())}


def test_baseline_starts_four_nodes_in_four_processes(baseline):
    started = _started_pids(baseline)
    assert sorted(started) == ['camera', 'detector', 'image_stats', 'monitor'], \
        baseline.output()
    assert 'process has died' not in baseline.output()


def test_baseline_is_configured_wastefully(baseline, camera):
    detector = labkit.read_parameters('/detector')
    assert camera['fps'] > detector['detect_rate']
    assert camera['reliability'] == detector['reliability'] == 'reliable'
    assert camera['depth'] > 1 and detector['depth'] > 1


def test_rates_and_sizes_match_the_configuration(baseline, camera):
    detect_rate = labkit.read_parameters('/detector')['detect_rate']
    rates = measure_rates({'/image': 'sensor_msgs/msg/Image',
                           '/detections': 'std_msgs/msg/Float32'}, window=WINDOW)
    image, detections = rates['/image'], rates['/detections']
    # Generous bands: a shared CI machine may drop frames, never add them.
    assert camera['fps'] / 3 <= image.hz <= camera['fps'] * 1.2, image
    assert detect_rate / 3 <= detections.hz <= detect_rate * 1.2, detections
    pixels = camera['width'] * camera['height'] * CHANNELS['rgb8']
    header = len(serialize_message(Image(
        height=camera['height'], width=camera['width'], encoding='rgb8',
        step=camera['width'] * CHANNELS['rgb8'], header=_header('camera'))))
    assert image.size == pixels + header, image
    assert detections.size == len(serialize_message(Float32())), detections
    assert image.bytes_per_second == pytest.approx(image.hz * image.size)


def _header(frame_id: str):
    message = Image()
    message.header.frame_id = frame_id
    return message.header


def test_process_usage_measures_the_launch_processes(baseline):
    usage = process_usage(baseline, window=WINDOW)
    started = _started_pids(baseline)
    by_pid = {item.pid: item for item in usage}
    assert set(started.values()) | {baseline.pid} == set(by_pid), usage
    for name, pid in started.items():
        assert by_pid[pid].name == name
        assert by_pid[pid].rss == pytest.approx(psutil.Process(pid).memory_info().rss,
                                                rel=0.5)
    camera = by_pid[started['camera']]
    monitor = by_pid[started['monitor']]
    # Drawing and sending 30 large frames a second costs far more than
    # counting 5 small messages: the ratio the lesson reports.
    assert camera.cpu_percent > 3 * monitor.cpu_percent, usage
    assert usage == sorted(usage, key=lambda item: item.cpu_percent, reverse=True)
