"""Checks of lesson 6.9 (Debugging multi-node communication with an assistant):
the speed governor, started after the one publish of the speed limit, must
get it anyway.  Judged on the running system (the launch log, and a late
subscriber of the check's own), never on the text of the file."""
from __future__ import annotations

import re
import subprocess
import time
from dataclasses import dataclass

from labkit.background import Background
from labkit.commands import launch
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

LIMIT_FILE = 'ex69_speed_limit.launch.py'
LIMIT = '0.30'
PUBLISHED = re.compile(r'\[limit_server\]: Published speed limit')
RECEIVED = re.compile(r'\[speed_governor\]: Speed limit (\d+\.\d+) m/s received')
WAITING = re.compile(r'\[speed_governor\]: No speed limit received yet')
#: The governor's own warning (the server's "requesting incompatible QoS" may be
#: about any subscriber, e.g. the check's own late one).
INCOMPATIBLE = re.compile(r"\[speed_governor\]: New publisher discovered on topic 'speed_limit', "
                          r'offering incompatible QoS.*')
GOVERNOR_STARTED = re.compile(r'^\[INFO\] \[(speed_governor-\d+)\]: process started')
DIED = re.compile(r'^\[ERROR\] \[(?P<process>[^\]]+)\]: process has died '
                  r'.*exit code (?P<code>-?\d+)')
#: The governor warns every 2 s while it has no limit; a governor that can get
#: the kept limit has it long before its second warning, so the check judges then.
WARNINGS_BEFORE_JUDGING = 2
#: Only stops a launch that never gets that far from hanging the check.
HANG_GUARD = 30.0
#: How long the check's own late subscriber listens for the kept limit.
LATE_ECHO_WAIT = 5.0


@dataclass
class LimitRun:
    """What the student's launch printed, and what a late subscriber heard."""

    command: str
    #: everything the launch printed; `before_echo`: up to the check's own subscriber
    lines: list[str]
    before_echo: list[str]
    exited_by_itself: bool
    late_echo: str


def _settled(lines: list[str]) -> bool:
    """The governor has its limit, or has warned long enough, or a process died."""
    text = '\n'.join(lines)
    return bool(RECEIVED.search(text)) or len(WAITING.findall(text)) >= WARNINGS_BEFORE_JUDGING \
        or any(DIED.match(line) for line in lines)


def _late_echo(package: StudentPackage) -> str:
    """`ros2 topic echo` joining now, asking for a kept message (transient_local)."""
    result = subprocess.run(
        ['ros2', 'topic', 'echo', '/speed_limit', 'std_msgs/msg/Float32', '--once',
         '--qos-durability', 'transient_local', '--qos-reliability', 'reliable',
         '--timeout', f'{LATE_ECHO_WAIT:g}'],
        env=package.environment(), cwd=package.workspace, capture_output=True, text=True,
        timeout=HANG_GUARD)
    return result.stdout


def run_limits(package: StudentPackage) -> LimitRun:
    """Launch the student's file, wait until the governor's fate is known, ask
    with a late subscriber of our own, and stop the launch."""
    running: Background = launch(package.name, LIMIT_FILE, env=package.environment(),
                                 cwd=package.workspace)
    try:
        deadline = time.monotonic() + HANG_GUARD
        while running.poll() is None and time.monotonic() < deadline \
                and not _settled(running.lines):
            time.sleep(0.1)
        exited = running.poll() is not None
        before_echo = running.lines
        echo = '' if exited else _late_echo(package)
    finally:
        running.stop()
    return LimitRun(running.command, running.lines, before_echo, exited, echo)


def _deaths(lines: list[str]) -> list[str]:
    """'limit_server-1 died (exit code 1): ValueError: ...' for each process that died."""
    deaths = []
    for number, line in enumerate(lines):
        if not (match := DIED.match(line)):
            continue
        process = match['process']
        errors = [earlier.removeprefix(f'[{process}] ') for earlier in lines[:number]
                  if re.match(rf'^\[{re.escape(process)}\] \w+(?:Error|Exception): ', earlier)]
        why = f': {errors[-1]}' if errors else ''
        deaths.append(f'{process} died (exit code {match["code"]}){why}')
    return deaths


def _order_kept(verdict: Verdict, lines: list[str]) -> bool:
    """The governor's process started after the server's first publish line."""
    published = next((n for n, line in enumerate(lines) if PUBLISHED.search(line)), None)
    started = next((n for n, line in enumerate(lines) if GOVERNOR_STARTED.match(line)), None)
    if started is None:
        return verdict.fail('the governor was never started: the launch must start it at '
                            'the server\'s "Published speed limit" line')
    return verdict.expect(
        published is not None and published < started,
        'the governor started after the server published the limit (order kept)',
        'the governor started before the server published the limit: keep the OnProcessIO '
        'handler that starts it at the "Published speed limit" line, and make the limit '
        'reach a governor that joins late instead')


def _governor_has_limit(verdict: Verdict, run: LimitRun) -> bool:
    text = '\n'.join(run.lines)
    received = RECEIVED.findall(text)
    if received:
        return verdict.expect(received[0] == LIMIT,
                              f'/speed_governor logs the limit ({received[0]} m/s received)',
                              f'/speed_governor received {received[0]} m/s, expected {LIMIT}: '
                              'leave max_speed at its default')
    if incompatible := INCOMPATIBLE.search('\n'.join(run.before_echo)):
        return verdict.fail(f'/speed_governor never received the speed limit; the launch log '
                            f'says: "{incompatible.group(0)}". The publisher and the '
                            'subscription must agree: give both nodes the same durability')
    if run.late_echo:
        return verdict.fail('/speed_governor never received the speed limit, although the '
                            'server keeps it (a late transient_local subscriber got it): its '
                            'subscription is volatile and does not ask for kept messages')
    return verdict.fail('/speed_governor never received the speed limit (it keeps warning "No '
                        'speed limit received yet"): the one publish happened before it '
                        'started, and nothing kept the limit for a subscriber that joins late')


def check_speed_limit(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The governor gets the limit, started after the publish; a late subscriber gets it too."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = run_limits(package)
    deaths = _deaths(run.lines)
    for death in deaths:
        verdict.fail(f'{death}. Read that error, fix the value that causes it, and '
                     'rebuild')
    if run.exited_by_itself and not deaths:
        verdict.fail(f'`{run.command}` ended by itself; its last lines:\n      '
                     + '\n      '.join(run.lines[-5:]))
    if deaths or run.exited_by_itself:
        return verdict
    _order_kept(verdict, run.lines)
    _governor_has_limit(verdict, run)
    got = re.match(r'data: (\S+)', run.late_echo)
    verdict.expect(got is not None,
                   f'a late transient_local subscriber gets the limit too (data: {got[1]})'
                   if got else '',
                   'a late transient_local subscriber (`ros2 topic echo /speed_limit '
                   "--qos-durability transient_local`) got nothing: the server's publisher "
                   'keeps no limit for subscribers that join later')
    return verdict


EXERCISES = (
    Exercise('ex69_speed_limit', 'Exercise 6.9.1 (a limit for a late governor)',
             ('launch/' + LIMIT_FILE,), check_speed_limit),
)
