"""Checks of lesson 6.6 (Events and processes).

The check plays the sensor's hardware.  It starts the student's launch file
as a terminal would, holds the sensor's process still for a few seconds as
it starts (slow calibration: a TimerAction's guess or OnProcessStart's "the
process exists" comes too early, only the sensor's own "ready" line is
right), lets it run until the processor gets readings, then kills it (the
hardware failed) and watches whether the launch shuts itself down.  It
judges the launch log only: the order of the lines and whether the launch
ended, never the text of the file.
"""
from __future__ import annotations

import os
import re
import signal
import time
from dataclasses import dataclass, field

from labkit.background import Background
from labkit.commands import launch
from labkit.errors import LabkitError
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LAUNCH_ERROR
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

CRITICAL_FILE = 'ex66_critical_sensor.launch.py'
READY = 'Publishing distance readings'
SENSOR_STARTED = re.compile(r'^\[INFO\] \[sensor_publisher-\d+\]: process started with pid '
                            r'\[(\d+)\]')
SENSOR_READY = re.compile(r'^\[sensor_publisher-\d+\] .*\]: ' + READY)
PROCESSOR_STARTED = re.compile(r'^\[INFO\] \[data_processor-\d+\]: process started')
PROCESSOR_RECEIVED = r'^\[data_processor-\d+\] .*\]: Received'
SENSOR_DIED = re.compile(r'^\[ERROR\] \[sensor_publisher-\d+\]: process has died')
#: Seconds the check holds the sensor still as it starts: the slow calibration.
CALIBRATION = 3.0
#: Hang guards (never speed limits): for the launch to come up, and to end after the death.
STARTUP_GUARD = 30.0
SHUTDOWN_GUARD = 15.0
FIX_START = ("start it from RegisterEventHandler(OnProcessIO(target_action=sensor, "
             "on_stderr=...)), returning the processor's Node only for the chunk of output "
             f"that contains b'{READY}'")
FIX_SHUTDOWN = ("add RegisterEventHandler(OnProcessExit(target_action=sensor, "
                "on_exit=[EmitEvent(event=Shutdown(reason='the sensor died'))]))")


@dataclass
class SensorTrial:
    """What the launch did while the check played the sensor's hardware."""

    command: str
    lines: list[str] = field(default_factory=list)
    returncode: int | None = None
    sensor_pid: int | None = None
    killed: bool = False
    ended_after_death: bool = False

    def first(self, pattern: re.Pattern) -> int | None:
        """Index of the first launch-log line matching `pattern`, or None."""
        return next((i for i, line in enumerate(self.lines) if pattern.search(line)), None)

    def count(self, pattern: re.Pattern) -> int:
        return sum(bool(pattern.search(line)) for line in self.lines)


def _signal(pid: int, sig: signal.Signals) -> None:
    try:
        os.kill(pid, sig)
    except ProcessLookupError:
        pass


def _wait_until_ended(running: Background, guard: float) -> bool:
    deadline = time.monotonic() + guard
    while running.running and time.monotonic() < deadline:
        time.sleep(0.1)
    return not running.running


def _play_the_hardware(running: Background, trial: SensorTrial) -> None:
    """Hold the sensor still while it 'calibrates', wait for readings, then kill it."""
    started = running.wait_for_output(SENSOR_STARTED.pattern, timeout=STARTUP_GUARD)
    trial.sensor_pid = int(SENSOR_STARTED.match(started).group(1))
    _signal(trial.sensor_pid, signal.SIGSTOP)
    try:
        time.sleep(CALIBRATION)  # the stimulus: a calibration this long, not a wait for a state
    finally:
        _signal(trial.sensor_pid, signal.SIGCONT)
    running.wait_for_output(SENSOR_READY.pattern, timeout=STARTUP_GUARD)
    try:  # a processor that never starts is judged below, from the log
        running.wait_for_output(PROCESSOR_RECEIVED, timeout=STARTUP_GUARD)
    except LabkitError:
        pass
    _signal(trial.sensor_pid, signal.SIGKILL)
    trial.killed = True
    trial.ended_after_death = _wait_until_ended(running, SHUTDOWN_GUARD)


def run_trial(package: StudentPackage) -> SensorTrial:
    """Launch the student's file and play the sensor's hardware against it."""
    running = launch(package.name, CRITICAL_FILE, env=package.environment(),
                     cwd=package.workspace)
    trial = SensorTrial(running.command)
    try:
        _play_the_hardware(running, trial)
    except LabkitError:
        pass  # the launch ended or never got so far: the log says why
    finally:
        if trial.sensor_pid is not None:
            _signal(trial.sensor_pid, signal.SIGCONT)
        trial.returncode = running.stop()
        trial.lines = running.lines
    return trial


def _sensor_started(verdict: Verdict, trial: SensorTrial) -> bool:
    errors = [line for line in trial.lines if LAUNCH_ERROR.match(line)]
    if errors:
        return verdict.fail(f'`{trial.command}` stopped with an error:\n      '
                            + '\n      '.join(errors)).passed
    ready = trial.first(SENSOR_READY) is not None
    return verdict.expect(trial.sensor_pid is not None and ready,
                          'sensor_publisher starts and gets ready',
                          "sensor_publisher never got ready: keep the starter's "
                          "Node(package='my_robot_pkg', executable='sensor_publisher', ...) "
                          'in the LaunchDescription')


def _processor_after_ready(verdict: Verdict, trial: SensorTrial) -> None:
    ready, started = trial.first(SENSOR_READY), trial.first(PROCESSOR_STARTED)
    if started is None:
        verdict.fail(f'data_processor never started: {FIX_START}')
        return
    if ready is not None and started < ready:
        verdict.fail(f"data_processor started before the sensor was ready (the sensor said "
                     f"'{READY}' {ready - started} lines of the launch log later; the check "
                     f'held the sensor still for {CALIBRATION:g} s as it started, like slow '
                     'hardware). Listing it after the sensor, a TimerAction or OnProcessStart '
                     f'only guess or watch the process, not the node: {FIX_START}')
        return
    times = trial.count(PROCESSOR_STARTED)
    verdict.expect(times == 1, "data_processor starts after the sensor's ready line",
                   f'data_processor was started {times} times: return its Node only for the '
                   f"chunk that contains b'{READY}', and None for every other chunk")


def _shutdown_after_death(verdict: Verdict, trial: SensorTrial) -> None:
    if not trial.killed:
        verdict.fail('the check could not get as far as killing the sensor: the launch ended '
                     'first; its last lines:\n      ' + '\n      '.join(trial.lines[-5:]))
        return
    died = trial.first(SENSOR_DIED)
    verdict.expect(trial.ended_after_death and died is not None,
                   'the launch shut down when the sensor died',
                   'the launch kept running after the sensor died (the check killed '
                   f'sensor_publisher; {SHUTDOWN_GUARD:g} s later the launch and the '
                   f'processor still ran): {FIX_SHUTDOWN}')


def check_critical_sensor(package: StudentPackage, verdict: Verdict) -> Verdict:
    """data_processor starts after the sensor's ready line; the sensor's death ends the launch."""
    if not requirements.files_installed(verdict, package):
        return verdict
    trial = run_trial(package)
    if not _sensor_started(verdict, trial):
        return verdict
    _processor_after_ready(verdict, trial)
    _shutdown_after_death(verdict, trial)
    return verdict


EXERCISES = (
    Exercise('ex66_critical_sensor',
             'Exercise 6.6.1 (start when ready, stop when the sensor dies)',
             ('launch/' + CRITICAL_FILE,), check_critical_sensor),
)
