"""comms_demo_pkg (lesson 6.9): the speed governor joins after the one speed
limit was published, so with volatile durability it never receives it; with
transient_local on both sides it does.

The governor is started by the launch only after the server's "Published
speed limit" line, so the order is fixed and the tests wait for log lines,
never for time.  Each test stops its launch before the next one starts (the
tests share a ROS domain, and a transient_local publisher in one would feed
a subscriber of the other).
"""
from __future__ import annotations

import re
import subprocess

import labkit
from textbook import paths

from .._polling import wait_for

HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
NODES = ['/limit_server', '/speed_governor']
WARNING = r'\[speed_governor\]: No speed limit received yet; holding the robot still'
RECEIVED = r'\[speed_governor\]: Speed limit (\d+\.\d\d) m/s received'
#: How long a late `ros2 topic echo --once` listens where nothing may arrive.
ECHO_WAIT = '3'


def _count(run: labkit.Background, pattern: str) -> int:
    return len(re.findall(pattern, run.output()))


def _ros2(env: dict[str, str], *words: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(['ros2', *words], env=env, cwd=paths.WORKSPACE,
                          capture_output=True, text=True, timeout=HANG_GUARD)


def _late_echo(env: dict[str, str], *timeout: str) -> str:
    """What a subscriber that asks for the kept message hears, joining after the publish."""
    return _ros2(env, 'topic', 'echo', '/speed_limit', '--once',
                 '--qos-durability', 'transient_local', *timeout).stdout


def _topic_info(env: dict[str, str], durability: str) -> str:
    """`ros2 topic info -v /speed_limit` once it shows both endpoints (discovery takes a moment)."""
    return wait_for(lambda: (info := _ros2(env, 'topic', 'info', '/speed_limit', '-v').stdout)
                    .count(f'Durability: {durability}') == 2 and info, HANG_GUARD,
                    f'both /speed_limit endpoints with durability {durability}')


def test_broken_launch_governor_never_receives_the_limit(ros_env):
    with labkit.launch('comms_demo_pkg', 'limits_broken.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as run:
        run.wait_for_output(r'\[limit_server\]: Published speed limit 0\.30 m/s',
                            timeout=HANG_GUARD)
        run.wait_for_nodes(NODES, timeout=HANG_GUARD)
        wait_for(lambda: _count(run, WARNING) >= 2, HANG_GUARD,
                 "the governor's second 'No speed limit' warning")
        output = run.output()
        assert not re.search(RECEIVED, output), output
        assert 'process has died' not in output, output
        # The governor was started after the publish line, never before it.
        assert output.index('Published speed limit') < output.index(
            '[speed_governor-2]: process started'), output

        # The graph looks connected: one publisher, one subscription, same type.
        info = _topic_info(ros_env, 'VOLATILE')
        assert 'Publisher count: 1' in info and 'Subscription count: 1' in info, info

        # Nothing is kept for a subscriber that asks for it: the publisher is volatile.
        echo = _late_echo(ros_env, '--timeout', ECHO_WAIT)
        assert 'data:' not in echo, echo

        # Published again while the governor listens, the limit does arrive, and
        # the second publish line starts no second governor.
        assert _ros2(ros_env, 'param', 'set', '/limit_server', 'max_speed', '0.5').returncode == 0
        run.wait_for_output(r'\[speed_governor\]: Speed limit 0\.50 m/s received',
                            timeout=HANG_GUARD)
        exit_code = run.stop()
    output = run.output()
    assert _count(run, r'\[speed_governor-\d+\]: process started') == 1, output
    assert re.findall(RECEIVED, output) == ['0.50'], output
    assert exit_code == 0, output


def test_fixed_launch_governor_receives_the_limit(ros_env):
    with labkit.launch('comms_demo_pkg', 'limits_fixed.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as run:
        run.wait_for_output(RECEIVED, timeout=HANG_GUARD)
        output = run.output()
        assert output.index('Published speed limit 0.30 m/s') < output.index(
            '[speed_governor-2]: process started'), output
        assert re.findall(RECEIVED, output) == ['0.30'], output

        info = _topic_info(ros_env, 'TRANSIENT_LOCAL')
        assert 'Publisher count: 1' in info and 'Subscription count: 1' in info, info

        # Joining even later than the governor, a transient_local subscriber gets it too.
        echo = _late_echo(ros_env)
        assert re.match(r'data: 0\.3\d*\n', echo), echo
        exit_code = run.stop()
    assert re.findall(RECEIVED, run.output()) == ['0.30'], run.output()
    assert exit_code == 0, run.output()
