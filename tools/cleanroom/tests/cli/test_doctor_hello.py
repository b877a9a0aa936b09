"""`ros2 doctor hello` (and `ros2 wtf hello`) in Jazzy's words (recorded from the reference).

The command publishes `hello, it's me <host>` on /canyouhearme and sends it
to multicast group 225.0.0.1:49150; its tables count what other hosts send.
Alone in the module's domain on one host, its tables stay empty (a host's own
messages are not counted).  Other hosts are played by `ros2 topic pub` and by
datagrams this module sends, as they were on the reference.  The multicast
group is shared by the whole machine, so the tests that use it run in one
xdist worker.
"""
from __future__ import annotations

import signal
import socket
import threading
import time

import pytest

pytestmark = pytest.mark.xdist_group('doctor_hello_multicast')

HELLO_HELP = """\
usage: ros2 doctor hello [-h] [-t [TOPIC]] [-ep N] [-pp N] [--ttl TTL] [-1]

Check network connectivity between multiple hosts

options:
  -h, --help            show this help message and exit
  -t [TOPIC], --topic [TOPIC]
                        Name of ROS topic to publish to (default:
                        '/canyouhearme')
  -ep N, --emit-period N
                        Time period to publish/send one message (default:
                        0.1s)
  -pp N, --print-period N
                        Time period to print summary table (default: 1.0s)
  --ttl TTL             TTL for multicast send (default: None)
  -1, --once            Publish and multicast send for one emit period then
                        exit; used in test case.
"""

DOCTOR_HELP = """\
usage: ros2 doctor [-h] [--report | --report-failed] [--exclude-packages]
                   [--include-warnings]
                   Call `ros2 doctor <command> -h` for more detailed usage.
                   ...

Check ROS setup and other potential issues

options:
  -h, --help            show this help message and exit
  --report, -r          Print all reports.
  --report-failed, -rf  Print reports of failed checks only.
  --exclude-packages, -ep
                        Exclude package checks or report.
  --include-warnings, -iw
                        Include warnings as failed checks. Warnings are
                        ignored by default.

Commands:
  hello  Check network connectivity between multiple hosts

  Call `ros2 doctor <command> -h` for more detailed usage.
"""

WTF_HELP_HEAD = """\
usage: ros2 wtf [-h] [--report | --report-failed] [--exclude-packages]
                [--include-warnings]
                Call `ros2 wtf <command> -h` for more detailed usage. ...

Use `wtf` as alias to `doctor`
"""

WTF_UNKNOWN_VERB = """\
usage: ros2 wtf [-h] [--report | --report-failed] [--exclude-packages]
                [--include-warnings]
                Call `ros2 wtf <command> -h` for more detailed usage. ...
ros2 wtf: error: argument Call `ros2 wtf <command> -h` for more detailed usage.: \
invalid choice: 'nosuch' (choose from 'hello')
"""

HELLO_USAGE = 'usage: ros2 doctor hello [-h] [-t [TOPIC]] [-ep N] [-pp N] [--ttl TTL] [-1]\n'
NOT_POSITIVE = 'value must be a positive {type_.__name__}'

ONCE = """\
MULTIMACHINE COMMUNICATION SUMMARY
Topic: /canyouhearme, Published Msg Count: 1
Subscribed from:
                Hostname             Msg Count /1.0s
Multicast Group/Port: 225.0.0.1/49150, Sent Msg Count: 1
Received from:
                Hostname             Msg Count /1.0s
------------------------------------------------------------
"""

ONCE_ON_FOO = ONCE.replace('/canyouhearme', 'foo').replace('/1.0s', '/0.25s')
RULE = '-' * 60 + '\n'
OTHER_HOST = "{data: \"hello, it's me otherhost\"}"


def test_hello_help(ros2):
    result = ros2('doctor', 'hello', '-h', env={'COLUMNS': '80'})
    assert (result.returncode, result.stdout) == (0, HELLO_HELP)
    wtf = ros2('wtf', 'hello', '-h', env={'COLUMNS': '80'})
    assert wtf.stdout == HELLO_HELP.replace('ros2 doctor hello', 'ros2 wtf hello')


def test_doctor_help_lists_hello(ros2):
    result = ros2('doctor', '-h', env={'COLUMNS': '80'})
    assert (result.returncode, result.stdout) == (0, DOCTOR_HELP)


def test_wtf_names_itself(ros2):
    result = ros2('wtf', '-h', env={'COLUMNS': '80'})
    assert result.stdout.startswith(WTF_HELP_HEAD)
    assert result.stdout.endswith('  Call `ros2 wtf <command> -h` for more detailed usage.\n')
    unknown = ros2('wtf', 'nosuch', env={'COLUMNS': '80'})
    assert (unknown.returncode, unknown.stderr) == (2, WTF_UNKNOWN_VERB)


def test_report_and_report_failed_exclude_each_other(ros2):
    result = ros2('doctor', '-r', '-rf', env={'COLUMNS': '80'})
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == \
        'ros2 doctor: error: argument --report-failed/-rf: not allowed with argument --report/-r'


@pytest.mark.parametrize(('args', 'message'), [
    (['--ttl', '0'], f'argument --ttl: {NOT_POSITIVE}'),
    (['--ttl', '1.5'], f'argument --ttl: {NOT_POSITIVE}'),
    (['-ep', 'abc'], f'argument -ep/--emit-period: {NOT_POSITIVE}'),
    (['-pp', '0'], f'argument -pp/--print-period: {NOT_POSITIVE}'),
    (['-ep', '-1'], 'argument -ep/--emit-period: expected one argument'),
])
def test_periods_and_ttl_must_be_positive(ros2, args, message):
    result = ros2('doctor', 'hello', *args, '--once', env={'COLUMNS': '80'})
    assert (result.returncode, result.stdout, result.stderr) == (
        2, '', f'{HELLO_USAGE}ros2 doctor hello: error: {message}\n')


def test_once_prints_one_summary_of_one_emit_period(ros2):
    result = ros2('doctor', 'hello', '--once')
    assert (result.returncode, result.stdout, result.stderr) == (0, ONCE, '')


def test_once_with_a_topic_and_a_print_period(ros2):
    result = ros2('wtf', 'hello', '-t', 'foo', '-pp', '0.25', '--once')
    assert (result.returncode, result.stdout, result.stderr) == (0, ONCE_ON_FOO, '')


def test_a_topic_option_without_a_name_is_rclpy_s_error(ros2):
    result = ros2('doctor', 'hello', '-t', '--once')
    assert (result.returncode, result.stdout, result.stderr) == (
        1, '', 'failed to validate name: topic_name argument is null, at '
               '/project/src/rcl/validate_topic_name.c:35\n')


def test_a_ttl_beyond_a_signed_byte_is_a_traceback(ros2):
    result = ros2('doctor', 'hello', '--ttl', '200', '--once')
    assert (result.returncode, result.stdout) == (1, '')
    assert result.stderr.splitlines()[-1] == \
        'struct.error: byte format requires -128 <= number <= 127'


def read_summary(proc) -> list[str]:
    """The lines of the next summary block `proc` prints (up to its rule)."""
    lines = []
    while not lines or lines[-1] != RULE:
        line = proc.stdout.readline()
        assert line, f'ros2 doctor hello ended early: {proc.stderr.read()}'
        lines.append(line)
    return lines


def rows(block: list[str], table: str) -> list[str]:
    """The host rows of one table ('Subscribed from:' or 'Received from:') of a block."""
    start = block.index(table + '\n') + 2  # past the Hostname header
    end = next(i for i in range(start, len(block)) if not block[i].startswith(' ' * 16))
    return [line.rstrip('\n') for line in block[start:end]]


def send_datagrams(text: str, count: int) -> None:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP) as sock:
        for _ in range(count):
            sock.sendto(text.encode(), ('225.0.0.1', 49150))
            time.sleep(0.02)


def test_other_hosts_are_counted_per_print_period(ros2_background):
    ros2_background('topic', 'pub', '-r', '10', '/canyouhearme', 'std_msgs/msg/String', OTHER_HOST)
    hello = ros2_background('doctor', 'hello')
    block = read_summary(hello)
    for _ in range(15):  # until discovery has brought the other publisher
        if rows(block, 'Subscribed from:'):
            break
        block = read_summary(hello)
    row = rows(block, 'Subscribed from:')[0]
    assert row.startswith(' ' * 16 + 'otherhost            ') and len(row) == 47, row
    # Right after a summary: all of them land in the next period.
    send_datagrams("hello, it's me farhost", 3)
    send_datagrams(f"hello, it's me {socket.gethostname()}", 3)  # this host's: not counted
    send_datagrams('x 12345678901234567890', 1)  # the host is the last word
    block = read_summary(hello)
    assert rows(block, 'Received from:') == [
        '                farhost              3         ',
        '                12345678901234567890 1         ']
    assert block[0] == 'MULTIMACHINE COMMUNICATION SUMMARY\n'
    assert block[4 + len(rows(block, 'Subscribed from:'))].startswith(
        'Multicast Group/Port: 225.0.0.1/49150, Sent Msg Count: ')
    assert rows(read_summary(hello), 'Received from:') == []  # counts start again


def test_ctrl_c_ends_it_quietly_with_exit_code_0(ros2_background):
    hello = ros2_background('doctor', 'hello')
    read_summary(hello)
    hello.send_signal(signal.SIGINT)
    assert hello.wait(timeout=10) == 0
    assert hello.stderr.read() == ''


def test_an_empty_message_stops_the_summaries(ros2, ros2_background):
    """The sender is the message's last word: an empty message kills the spin
    thread, which also ran the emit and print timers; Ctrl-C still ends it with 0."""
    hello = ros2_background('doctor', 'hello')
    read_summary(hello)
    printed: list[float] = []  # when each later line came
    reader = threading.Thread(
        target=lambda: printed.extend(time.monotonic() for _ in hello.stdout), daemon=True)
    reader.start()
    sent = ros2('topic', 'pub', '-t', '3', '-w', '1', '/canyouhearme', 'std_msgs/msg/String',
                '{data: ""}')
    assert sent.returncode == 0, sent.stderr
    delivered = time.monotonic()
    time.sleep(2.5)
    hello.send_signal(signal.SIGINT)
    assert hello.wait(timeout=10) == 0
    reader.join(timeout=5)
    assert not [when for when in printed if when > delivered + 0.5]
    stderr = hello.stderr.read()
    assert stderr.startswith('Exception in thread Thread-2 (spin):\n'), stderr
    assert stderr.splitlines()[-1] == 'IndexError: list index out of range'
