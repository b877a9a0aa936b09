"""Checks of lesson 6.10 (Optimising node configuration): a pipeline within a
budget.

Judged only on quantities a run gives the same way on any machine: the
parameters the running nodes use (read back from them), the processes the
launch starts (its own log), the size of the messages on /image and the rate
on /detections (a timer in the detector, so 5.0 Hz unless results are
skipped) and the monitor's reports.  Never CPU or memory: those depend on
the machine and on what else runs on it.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from rclpy.serialization import serialize_message
from sensor_msgs.msg import Image

from labkit.errors import LabkitError
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot, read_parameters
from labkit.rates import Rate, measure_rates

PIPELINE_FILE = 'ex610_light_pipeline.launch.py'
CAMERA, DETECTOR, MONITOR = '/camera', '/detector', '/monitor'
#: The budget of the exercise.
DETECT_RATE = 5.0  # results a second the detector must keep publishing
MAX_FPS = 10.0
MAX_WIDTH, MAX_HEIGHT = 640, 480
MAX_PROCESSES = 3
#: What tuning_demo_pkg's camera declares (camera.py): name -> default.
CAMERA_DEFAULTS: dict[str, Any] = {'width': 1280, 'height': 720, 'fps': 30.0}
#: Seconds of measuring /image and /detections while the launch runs.
WINDOW = 3.0
MONITOR_COUNTS = re.compile(r'\[monitor\]: [1-9]\d* detections in the last second')
PIPELINE_HINT = ("run camera and detector in one process (Node(package='tuning_demo_pkg', "
                 "executable='pipeline'), without name=)")


@dataclass
class Observed:
    """What the check read while the launch ran."""

    parameters: dict[str, dict[str, Any]] = field(default_factory=dict)  # node -> parameters
    rates: dict[str, Rate] = field(default_factory=dict)


def _observe(snapshot: GraphSnapshot) -> Observed:
    observed = Observed()
    for node in (CAMERA, DETECTOR):
        if node in snapshot.nodes:
            try:
                observed.parameters[node] = read_parameters(node)
            except LabkitError:
                pass  # reported as "not running" / no values below
    observed.rates = measure_rates({'/image': 'sensor_msgs/msg/Image',
                                    '/detections': 'std_msgs/msg/Float32'}, window=WINDOW)
    return observed


def _largest_image_message() -> int:
    """Serialized bytes of a MAX_WIDTH x MAX_HEIGHT rgb8 frame as the camera sends it."""
    message = Image(width=MAX_WIDTH, height=MAX_HEIGHT, encoding='rgb8', step=MAX_WIDTH * 3)
    message.header.frame_id = 'camera'
    message.data = bytes(MAX_WIDTH * MAX_HEIGHT * 3)
    return len(serialize_message(message))


def _default_note(name: str, value: Any) -> str:
    """Why a camera parameter may still be at its default: a misspelled name."""
    if value != CAMERA_DEFAULTS[name]:
        return ''
    return (f"; {name} is {value}, the camera's default: does your launch file set the "
            f'parameter {name}, spelled exactly so? The camera ignores a name it does not '
            'declare, without a word')


def _processes(verdict: Verdict, run: LaunchProbe) -> None:
    count = len(run.processes)
    verdict.expect(count <= MAX_PROCESSES,
                   f'{count} processes for the nodes ({", ".join(run.processes)})',
                   f'{count} processes start ({", ".join(run.processes)}); the budget is '
                   f'{MAX_PROCESSES}: leave out image_stats, which the results do not need, '
                   f'or {PIPELINE_HINT}')


def _camera(verdict: Verdict, camera: dict[str, Any], detect_rate: float | None,
            image: Rate) -> None:
    fps = camera['fps']
    verdict.expect(fps <= MAX_FPS, f'the camera sends {fps} fps (at most {MAX_FPS})',
                   f'the camera sends {fps} fps; the budget is at most {MAX_FPS}: set its '
                   f'parameter fps' + _default_note('fps', fps))
    if detect_rate is not None:
        verdict.expect(fps >= 2 * detect_rate,
                       f'{fps} fps is at least twice detect_rate {detect_rate}',
                       f"the camera sends {fps} fps, less than twice the detector's "
                       f'detect_rate {detect_rate}: a detection tick may find no new frame '
                       'and skip its result; give the camera at least twice that rate')
    width, height = camera['width'], camera['height']
    fits = width <= MAX_WIDTH and height <= MAX_HEIGHT
    notes = _default_note('width', width) + _default_note('height', height)
    verdict.expect(fits, f'images of {width}x{height} (at most {MAX_WIDTH}x{MAX_HEIGHT})',
                   f"the camera's images are {width}x{height}; the budget is at most "
                   f'{MAX_WIDTH}x{MAX_HEIGHT}: set its parameters width and height' + notes)
    largest = _largest_image_message()
    if image.size is None:
        verdict.fail(f'no image arrived on /image in {WINDOW:g} s: does the camera publish, '
                     'with a QoS the other nodes match?')
    else:
        verdict.expect(image.size <= largest,
                       f'{image.size:,.0f} bytes per message on /image',
                       f'the messages on /image are {image.size:,.0f} bytes, more than the '
                       f'{largest:,} bytes of a {MAX_WIDTH}x{MAX_HEIGHT} rgb8 frame')


def _results(verdict: Verdict, run: LaunchProbe, detections: Rate) -> None:
    hz = detections.hz or 0.0
    verdict.expect(hz >= 0.95 * DETECT_RATE, f'/detections at {hz:.1f} Hz',
                   f'/detections at {hz:.1f} Hz in {WINDOW:g} s: below the {DETECT_RATE:g} '
                   'results a second the detector must publish; does it get a new frame '
                   'at every tick (camera fps), and is its detect_rate still '
                   f'{DETECT_RATE:g}?')
    reports = [line for line in run.lines if MONITOR_COUNTS.search(line)]
    verdict.expect(bool(reports), 'the monitor reports the detections',
                   'the monitor never reported a detection: start it '
                   "(Node(package='tuning_demo_pkg', executable='monitor', name='monitor'))"
                   ' and keep /detections flowing')


def check_light_pipeline(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Results at 5 Hz and reported, within the budget of rate, size and processes."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, PIPELINE_FILE, (CAMERA, DETECTOR, MONITOR), inspect=_observe)
    if not requirements.launch_ran(verdict, run):
        return verdict
    hints = {CAMERA: f'start it (executable camera, or {PIPELINE_HINT})',
             DETECTOR: f'the detector makes the results: keep it (executable detector, or '
                       f'{PIPELINE_HINT})',
             MONITOR: "start it: Node(package='tuning_demo_pkg', executable='monitor', "
                      "name='monitor')"}
    for node, how in hints.items():
        requirements.node_running(verdict, run, node, how)
    _processes(verdict, run)
    observed: Observed = run.inspected or Observed()
    detector = observed.parameters.get(DETECTOR, {})
    if CAMERA in observed.parameters:
        _camera(verdict, observed.parameters[CAMERA], detector.get('detect_rate'),
                observed.rates['/image'])
    if observed.rates:
        _results(verdict, run, observed.rates['/detections'])
    return verdict


EXERCISES = (
    Exercise('ex610_light_pipeline', 'Exercise 6.10.1 (a pipeline within a budget)',
             ('launch/' + PIPELINE_FILE,), check_light_pipeline),
)
