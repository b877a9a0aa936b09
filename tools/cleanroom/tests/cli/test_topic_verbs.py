"""`ros2 topic type|find|pub|bw|delay` against running nodes, with the texts, streams
and exit codes Jazzy's ros2 gave for the same graph (issue #21)."""
from __future__ import annotations

import os
import re
import select
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from builtin_interfaces.msg import Time
from geometry_msgs.msg import PoseArray, Twist
from ros2_cleanroom.message_fields import set_message_fields
from ros2_cleanroom.topic_statistics import BandwidthWindow, DelayWindow
from std_msgs.msg import String

EXTRA_NODES = str(Path(__file__).with_name('extra_nodes.py'))

TOPIC_HELP = """\
usage: ros2 topic [-h] [--include-hidden-topics]
                  Call `ros2 topic <command> -h` for more detailed usage. ...

Various topic related sub-commands

options:
  -h, --help            show this help message and exit
  --include-hidden-topics
                        Consider hidden topics as well

Commands:
  bw     Display bandwidth used by topic
  delay  Display delay of topic from timestamp in header
  echo   Output messages from a topic
  find   Output a list of available topics of a given type
  hz     Print the average publishing rate to screen
  info   Print information about a topic
  list   Output a list of available topics
  pub    Publish a message to a topic
  type   Print a topic's type

  Call `ros2 topic <command> -h` for more detailed usage.
"""

TYPE_HELP = """\
usage: ros2 topic type [-h] [--spin-time SPIN_TIME] [-s] [--no-daemon]
                       topic_name

Print a topic's type

positional arguments:
  topic_name            Name of the ROS topic to get type (e.g. '/chatter')

options:
  -h, --help            show this help message and exit
  --spin-time SPIN_TIME
                        Spin time in seconds to wait for discovery (only
                        applies when not using an already running daemon)
  -s, --use-sim-time    Enable ROS simulation time
  --no-daemon           Do not spawn nor use an already running daemon
"""

FIND_HELP = """\
usage: ros2 topic find [-h] [--spin-time SPIN_TIME] [-s] [--no-daemon] [-c]
                       [--include-hidden-topics]
                       topic_type

Output a list of available topics of a given type

positional arguments:
  topic_type            Name of the ROS topic type to filter for (e.g.
                        'std_msg/msg/String')

options:
  -h, --help            show this help message and exit
  --spin-time SPIN_TIME
                        Spin time in seconds to wait for discovery (only
                        applies when not using an already running daemon)
  -s, --use-sim-time    Enable ROS simulation time
  --no-daemon           Do not spawn nor use an already running daemon
  -c, --count-topics    Only display the number of topics discovered
  --include-hidden-topics
                        Consider hidden topics as well
"""

# Its usage lines are longer than this file's lines may be.
PUB_HELP = Path(__file__).with_name('topic_pub_help.expected').read_text()

BW_HELP = """\
usage: ros2 topic bw [-h] [--window WINDOW] [--spin-time SPIN_TIME] [-s] topic

Display bandwidth used by topic

positional arguments:
  topic                 Topic name to monitor for bandwidth utilization

options:
  -h, --help            show this help message and exit
  --window WINDOW, -w WINDOW
                        maximum window size, in # of messages, for calculating
                        rate (default: 100)
  --spin-time SPIN_TIME
                        Spin time in seconds to wait for discovery (only
                        applies when not using an already running daemon)
  -s, --use-sim-time    Enable ROS simulation time
"""

DELAY_HELP = """\
usage: ros2 topic delay [-h] [--window WINDOW] [--spin-time SPIN_TIME] [-s]
                        topic

Display delay of topic from timestamp in header

positional arguments:
  topic                 Topic name to calculate the delay for

options:
  -h, --help            show this help message and exit
  --window WINDOW, -w WINDOW
                        window size, in # of messages, for calculating rate,
                        string to (default: 10000)
  --spin-time SPIN_TIME
                        Spin time in seconds to wait for discovery (only
                        applies when not using an already running daemon)
  -s, --use-sim-time    Enable ROS simulation time
"""

WAITING = 'Waiting for at least 1 matching subscription(s)...'
BEGIN = 'publisher: beginning loop\n'


@pytest.fixture(scope='module')
def graph(start_node, daemon_listing, cli_env: dict[str, str]) -> Iterator[None]:
    """/chatter (String from the talker, Int32 from int_talker, heard by the listener),
    /cmd_vel (Twist) and the hidden /_hid, all up before the module's first listing."""
    extra = []
    for kind in ('hidden_talker', 'int_talker'):
        proc = subprocess.Popen([sys.executable, EXTRA_NODES, kind], env=cli_env,
                                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                start_new_session=True)
        extra.append(proc)
        assert proc.stdout.readline().startswith('ready '), f'{kind} did not start'
    for kind in ('talker', 'listener', 'twister'):
        start_node(kind)
    daemon_listing(
        ('topic', 'list', '-t', '--include-hidden-topics'),
        ['/_hid [std_msgs/msg/String]',
         '/chatter [std_msgs/msg/Int32, std_msgs/msg/String]',
         '/cmd_vel [geometry_msgs/msg/Twist]'])
    try:
        yield
    finally:
        for proc in extra:
            for sig in (signal.SIGINT, signal.SIGKILL):
                if proc.poll() is None:
                    os.killpg(proc.pid, sig)
                    try:
                        proc.wait(timeout=5)
                    except subprocess.TimeoutExpired:
                        continue
            proc.wait()


def _read_until(proc: subprocess.Popen, pattern: str, count: int,
                timeout: float = 25.0) -> list[str]:
    """Lines of `proc`'s stdout until `count` of them match `pattern` (or time runs out)."""
    lines: list[str] = []
    deadline = time.monotonic() + timeout
    while sum(1 for line in lines if re.fullmatch(pattern, line)) < count:
        remaining = deadline - time.monotonic()
        assert remaining > 0, f'only got {lines}'
        ready, _, _ = select.select([proc.stdout], [], [], remaining)
        if ready:
            line = proc.stdout.readline()
            assert line, f'the command ended: {lines}'
            lines.append(line.rstrip('\n'))
    return lines


def _interrupt(proc: subprocess.Popen) -> tuple[str, str, int]:
    """Ctrl-C the command's process group; its remaining output and exit code."""
    os.killpg(proc.pid, signal.SIGINT)
    out, err = proc.communicate(timeout=15)
    return out, err, proc.returncode


@pytest.mark.parametrize(('args', 'expected'), [
    (('topic', '-h'), TOPIC_HELP),
    (('topic', 'type', '-h'), TYPE_HELP),
    (('topic', 'find', '-h'), FIND_HELP),
    (('topic', 'pub', '-h'), PUB_HELP),
    (('topic', 'bw', '-h'), BW_HELP),
    (('topic', 'delay', '-h'), DELAY_HELP),
])
def test_help_is_jazzys(ros2, args, expected):
    result = ros2(*args, env={'COLUMNS': '80'})
    assert (result.stdout, result.returncode) == (expected, 0)


def test_type_missing_argument(ros2):
    result = ros2('topic', 'type', env={'COLUMNS': '80'})
    assert (result.stdout, result.returncode) == ('', 2)
    assert result.stderr == (
        'usage: ros2 topic type [-h] [--spin-time SPIN_TIME] [-s] [--no-daemon]\n'
        '                       topic_name\n'
        'ros2 topic type: error: the following arguments are required: topic_name\n')


def test_type_lists_every_type(ros2, graph):
    assert ros2('topic', 'type', '/cmd_vel').stdout == 'geometry_msgs/msg/Twist\n'
    result = ros2('topic', 'type', '/chatter')
    assert (result.stdout, result.stderr, result.returncode) == (
        'std_msgs/msg/Int32\nstd_msgs/msg/String\n', '', 0)


@pytest.mark.parametrize('topic', ['/nope', 'chatter', '/_hid'])
def test_type_unknown_relative_or_hidden_fails_silently(ros2, graph, topic):
    result = ros2('topic', 'type', topic, '--spin-time', '1')
    assert (result.stdout, result.stderr, result.returncode) == ('', '', 1)


@pytest.mark.parametrize(('args', 'expected'), [
    (('std_msgs/msg/String',), '/chatter\n'),
    (('std_msgs/msg/Int32',), '/chatter\n'),
    (('geometry_msgs/msg/Twist',), '/cmd_vel\n'),
    (('std_msgs/String',), ''),  # the type as the graph spells it, or nothing
    (('nope/msg/X',), ''),
    (('-c', 'std_msgs/msg/String'), '1\n'),
    (('-c', 'nope'), '0\n'),
    (('--include-hidden-topics', 'std_msgs/msg/String'), '/_hid\n/chatter\n'),
    (('-c', '--include-hidden-topics', 'std_msgs/msg/String'), '2\n'),
    (('--include-hidden-topics', 'rcl_interfaces/msg/ParameterEvent'), '/parameter_events\n'),
])
def test_find(ros2, graph, args, expected):
    result = ros2('topic', 'find', *args)
    assert (result.stdout, result.stderr, result.returncode) == (expected, '', 0)


def test_the_commands_own_include_hidden_flag_is_overridden(ros2, graph):
    assert ros2('topic', '--include-hidden-topics', 'find',
                'std_msgs/msg/String').stdout == '/chatter\n'


@pytest.mark.parametrize(('args', 'printed'), [
    (('std_msgs/msg/String', '{data: hi}'), "std_msgs.msg.String(data='hi')"),
    (('std_msgs/String', 'data: x'), "std_msgs.msg.String(data='x')"),
    (('std_msgs/msg/String', '{data: [1, 2]}'), "std_msgs.msg.String(data='[1, 2]')"),
    (('std_msgs/msg/Int32', '{data: 1.5}'), 'std_msgs.msg.Int32(data=1)'),
    (('std_msgs/msg/String',), "std_msgs.msg.String(data='')"),
    (('geometry_msgs/msg/Twist', '{linear: {x: 1}}'),
     'geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=1.0, y=0.0, z=0.0), '
     'angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0))'),
])
def test_pub_once(ros2, args, printed):
    result = ros2('topic', 'pub', '-1', '-w', '0', '/pub_test', *args)
    assert (result.stdout, result.stderr, result.returncode) == (
        f'{BEGIN}publishing #1: {printed}\n\n', '', 0)


def test_pub_stamp_now(ros2):
    result = ros2('topic', 'pub', '-1', '-w', '0', '/pub_test', 'std_msgs/msg/Header',
                  '{stamp: now, frame_id: f}')
    assert re.fullmatch(r"publisher: beginning loop\npublishing #1: std_msgs\.msg\.Header\("
                        r"stamp=builtin_interfaces\.msg\.Time\(sec=\d{10}, nanosec=\d+\), "
                        r"frame_id='f'\)\n\n", result.stdout)


@pytest.mark.parametrize(('args', 'message'), [
    (('std_msgs/msg/Nope',), 'The passed message type is invalid'),
    (('nope',), 'The passed message type is invalid'),
    (('nope', '3'), 'The passed message type is invalid'),
    (('std_msgs/msg/String', '3'), 'The passed value needs to be a dictionary in YAML format'),
    (('std_msgs/msg/String', ''), 'The passed value needs to be a dictionary in YAML format'),
    (('std_msgs/msg/String', '{bad: 1}'),
     "Failed to populate field: 'String' object has no attribute 'bad'"),
    (('geometry_msgs/msg/Twist', '{linear: {x: abc}}'),
     "Failed to populate field: could not convert string to float: 'abc'"),
    (('std_msgs/msg/Header', '{stamp: 5}'),
     "Failed to populate field: Value '5' is expected to be a dictionary but is a int"),
])
def test_pub_refuses(ros2, args, message):
    result = ros2('topic', 'pub', '-1', '-w', '0', '/pub_test', *args)
    assert (result.stdout, result.stderr, result.returncode) == ('', message + '\n', 1)


@pytest.mark.parametrize(('args', 'last_line'), [
    (('/pub_test', 'std_msgs/msg/String', 'data: [1'),
     "expected ',' or ']', but got '<stream end>'"),
    (('/bad name', 'std_msgs/msg/String'), '       ^'),
])
def test_pub_tracebacks(ros2, args, last_line):
    result = ros2('topic', 'pub', '-1', '-w', '0', *args)
    assert result.returncode == 1
    assert result.stderr.startswith('Traceback (most recent call last):\n')
    assert last_line in result.stderr.splitlines()[-6:]


@pytest.mark.parametrize(('args', 'error'), [
    (('-1', '-t', '2'), 'argument -t/--times: not allowed with argument -1/--once'),
    (('--stdin', 'std_msgs/msg/String', 'data: y'),
     'argument values: not allowed with argument --stdin'),
])
def test_pub_exclusive_options(ros2, args, error):
    if len(args) == 2:
        args = (*args, '/x', 'std_msgs/msg/String')
    else:
        args = (args[0], '/x', *args[1:])
    result = ros2('topic', 'pub', *args, env={'COLUMNS': '80'})
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == f'ros2 topic pub: error: {error}'


def test_pub_stdin(cli_env):
    result = subprocess.run([str(Path(sys.executable).parent / 'ros2'), 'topic', 'pub', '-1',
                             '-w', '0', '--stdin', '/pub_test', 'std_msgs/msg/String'],
                            input='data: fromstdin\n', env=cli_env, capture_output=True,
                            text=True, timeout=30)
    assert (result.stdout, result.returncode) == (
        f"{BEGIN}publishing #1: std_msgs.msg.String(data='fromstdin')\n\n", 0)


def test_pub_times_every_nth_to_a_subscriber(ros2, graph):
    result = ros2('topic', 'pub', '-t', '3', '-r', '10', '-p', '2', '/chatter',
                  'std_msgs/msg/String', '{data: a}')
    # a "Waiting" line for each second the subscriber is not yet matched (often one)
    *waiting, rest = result.stdout.split('\n', result.stdout.count(WAITING))
    assert set(waiting) <= {WAITING}
    assert rest == f"{BEGIN}publishing #2: std_msgs.msg.String(data='a')\n\n"
    assert result.returncode == 0


def test_pub_gives_up_waiting(ros2):
    result = ros2('topic', 'pub', '-1', '--max-wait-time-secs', '1.5', '/nobody',
                  'std_msgs/msg/String')
    assert result.stdout == f'{WAITING}\n{WAITING}\n'
    assert result.stderr == ('Timed out waiting for subscribers: Expected 1 subcribers but only '
                             'got 0 subscribers\n')
    assert result.returncode == 1


def test_pub_until_interrupted(ros2_background):
    proc = ros2_background('topic', 'pub', '-r', '20', '-w', '0', '/nobody',
                           'std_msgs/msg/String')
    lines = _read_until(proc, r'publishing #\d+: .*', 3)
    assert lines[:4] == ['publisher: beginning loop', "publishing #1: std_msgs.msg.String(data='')",
                         '', "publishing #2: std_msgs.msg.String(data='')"]
    out, err, code = _interrupt(proc)
    assert (err, code) == ('', 2)


def test_bw(ros2_background, graph):
    # /cmd_vel: /chatter carries two types in this module
    proc = ros2_background('topic', 'bw', '/cmd_vel')
    lines = _read_until(proc, r'\d+ B/s from \d+ messages', 2)
    assert 'Subscribed to [/cmd_vel]' in lines
    sizes = [line for line in lines if line.startswith('\t')]
    assert set(sizes) == {'\tMessage size mean: 52 B min: 52 B max: 52 B'}
    out, err, code = _interrupt(proc)
    assert (err, code) == ('', 2)


def test_bw_window(ros2_background, graph):
    proc = ros2_background('topic', 'bw', '-w', '3', '/cmd_vel')
    lines = _read_until(proc, r'\d+ B/s from 3 messages', 2)
    assert '\tMessage size mean: 52 B min: 52 B max: 52 B' in lines
    assert _interrupt(proc)[2] == 2


def test_bw_unpublished_topic_waits(ros2_background, graph):
    proc = ros2_background('topic', 'bw', '/nope')
    assert _read_until(proc, '.*', 1) == [
        'WARNING: topic [/nope] does not appear to be published yet']
    assert _interrupt(proc) == ('', '', 2)


def test_delay(ros2_background, graph):
    ros2_background('topic', 'pub', '-r', '10', '/stamped', 'geometry_msgs/msg/PointStamped',
                    '{header: {stamp: now}}')
    proc = ros2_background('topic', 'delay', '/stamped')
    lines = _read_until(proc, r'average delay: \d+\.\d{3}', 2)
    assert any(re.fullmatch(r'\tmin: \d+\.\d{3}s max: \d+\.\d{3}s std dev: \d+\.\d{5}s '
                            r'window: \d+', line) for line in lines)
    assert _interrupt(proc)[2] == 2


def test_delay_without_header(ros2, graph):
    result = ros2('topic', 'delay', '/cmd_vel')
    assert (result.stdout, result.stderr, result.returncode) == (
        '', 'msg does not have header\n', 1)


def test_message_fields_without_ros():
    msg = PoseArray()
    set_message_fields(msg, {'header': 'auto', 'poses': [{'position': {'x': 2}}]},
                       now=lambda: Time(sec=5))
    assert (msg.header.stamp.sec, msg.poses[0].position.x) == (5, 2.0)
    with pytest.raises(TypeError, match="Value '5' is expected to be a dictionary but is a int"):
        set_message_fields(Twist(), {'linear': 5})
    with pytest.raises(AttributeError, match="'String' object has no attribute 'bad'"):
        set_message_fields(String(), {'bad': 1})


def test_statistics_formats():
    bw = BandwidthWindow(100)
    for i in range(8):
        bw.add(i * 0.1, 20)
    assert bw.report(0.74) == ('216 B/s from 8 messages\n'
                               '\tMessage size mean: 20 B min: 20 B max: 20 B')
    big = BandwidthWindow(100)
    for i in range(10):
        big.add(i * 0.1, 1509)
    assert big.report(0.9455).startswith('15.96 KB/s from 10 messages\n'
                                         '\tMessage size mean: 1.51 KB min: 1.51 KB max: 1.51 KB')
    delay = DelayWindow(10)
    assert delay.report() is None
    delay.add(0.001)
    delay.add(0.002)
    assert delay.report() == ('average delay: 0.002\n'
                              '\tmin: 0.001s max: 0.002s std dev: 0.00050s window: 2')
    assert delay.report() is None
