"""The shared launch conformance suite (../shared/conformance), when present:
our launch, launch_ros and ros2 must behave as recorded from ROS 2 Jazzy."""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest
import yaml
from textbook import paths

SUITE = paths.ROOT.parent / 'shared' / 'conformance'

pytestmark = [
    pytest.mark.skipif(not SUITE.is_dir(), reason=f'no conformance suite at {SUITE}'),
    pytest.mark.timeout(1800),
]


def run_check(script: str, tmp_path, *extra: str) -> str:
    result = subprocess.run(
        [sys.executable, str(SUITE / script), '--python', sys.executable,
         '--workdir', str(tmp_path), '-v', *extra],
        cwd=tmp_path, env=dict(os.environ), capture_output=True, text=True, timeout=1700)
    return result.stdout + result.stderr


# 09_events races an OnProcessExit (the worker `exiter 0 0.3` ends) against a
# 0.5 s TimerAction for the number of the next process.  The golden was
# recorded where the worker lived longer than 0.5 s; on an idle machine of our
# kind the same rclpy build lives ~0.43 s, so the two listeners' numbers come
# out swapped.  That swap, and nothing else, is accepted for this case.
RACE_CASE = '09_events'
RACING_NODES = ('__node:=delayed', '__node:=after_worker')


def _verbose_processes(out: str, which: str) -> list[dict]:
    match = re.search(rf'^  {which} +processes: (.*)$', out, re.M)
    assert match, out
    return json.loads(match.group(1))


def _swap_racing_numbers(processes: list[dict]) -> list[dict]:
    """The records as they would be had the other side of the race won."""
    racers = [p for p in processes if any(node in p['cmd'] for node in RACING_NODES)]
    assert len(racers) == 2, processes
    names = [p['name'] for p in racers]
    swapped = [dict(p, name=name) for p, name in zip(racers, reversed(names), strict=True)]
    rest = [p for p in processes if p not in racers]
    return sorted(rest + swapped, key=lambda p: (p['name'], json.dumps(p['cmd'], sort_keys=True)))


def test_launch_api_conformance(tmp_path):
    out = run_check('check.py', tmp_path)
    if '32 passed, 0 failed' in out:
        return
    assert '31 passed, 1 failed' in out, out
    assert re.findall(r'^FAIL (\S+): (.+) differ$', out, re.M) == [(RACE_CASE, 'processes')], out
    want, got = _verbose_processes(out, 'want'), _verbose_processes(out, 'got')
    assert _swap_racing_numbers(got) == want, out


def test_launch_error_lines_conformance(tmp_path):
    """Every [ERROR] line of launch* loggers in the error cases, as Jazzy printed them."""
    out = run_check('check.py', tmp_path, '--suite', str(SUITE / 'errors'))
    cases = len(yaml.safe_load((SUITE / 'errors' / 'cases.yaml').read_text()))
    assert f'{cases} passed, 0 failed' in out, out


def test_frontends_conformance(tmp_path):
    """The XML and YAML launch files (and their errors), as Jazzy ran them."""
    out = run_check('check.py', tmp_path, '--suite', str(SUITE / 'frontends'))
    cases = len(yaml.safe_load((SUITE / 'frontends' / 'cases.yaml').read_text()))
    assert f'{cases} passed, 0 failed' in out, out


def test_ros2_cli_conformance(tmp_path):
    out = run_check('cli_check.py', tmp_path)
    assert '11 passed, 0 failed' in out, out


def test_race_allowance_accepts_the_swap_and_nothing_else():
    """The 09_events allowance must not hide any other difference."""
    want = json.loads((SUITE / 'goldens' / f'{RACE_CASE}.json').read_text())['processes']
    other_side_of_the_race = _swap_racing_numbers(want)
    assert other_side_of_the_race != want
    assert _swap_racing_numbers(other_side_of_the_race) == want

    wrong_command = json.loads(json.dumps(other_side_of_the_race))
    wrong_command[0]['cmd'].append('--extra')
    assert _swap_racing_numbers(wrong_command) != want

    missing_process = [p for p in other_side_of_the_race if '__node:=talker' not in p['cmd']]
    assert _swap_racing_numbers(missing_process) != want
