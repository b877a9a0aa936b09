"""`ros2 daemon` and the listing commands that ask it, as observed on Jazzy:
the first listing starts the daemon, later ones get its graph at once, and
`start|stop|status` answer in Jazzy's words with exit code 0."""
from __future__ import annotations

import psutil
from _polling import wait_for

DAEMON_HELP = """\
usage: ros2 daemon [-h]
                   Call `ros2 daemon <command> -h` for more detailed usage.
                   ...

Various daemon related sub-commands

options:
  -h, --help            show this help message and exit

Commands:
  start   Start the daemon if it isn't running
  status  Output the status of the daemon
  stop    Stop the daemon if it is running

  Call `ros2 daemon <command> -h` for more detailed usage.
"""


def _said(result) -> tuple[int, str]:
    return result.returncode, result.stdout


def _daemon_processes(domain: str) -> list[psutil.Process]:
    found = []
    for proc in psutil.process_iter(['cmdline']):
        cmdline = proc.info['cmdline'] or []
        if '--name' in cmdline and 'ros2-daemon' in cmdline \
                and cmdline[cmdline.index('--ros-domain-id') + 1] == domain:
            found.append(proc)
    return found


def test_start_stop_and_status_in_jazzys_words(ros2, cli_env):
    ros2('daemon', 'stop')
    assert _said(ros2('daemon', 'status')) == (0, 'The daemon is not running\n')
    assert _said(ros2('daemon', 'start')) == (0, 'The daemon has been started\n')
    assert _said(ros2('daemon', 'start')) == (0, 'The daemon is already running\n')
    assert _said(ros2('daemon', 'status')) == (0, 'The daemon is running\n')
    assert len(_daemon_processes(cli_env['ROS_DOMAIN_ID'])) == 1
    assert _said(ros2('daemon', 'stop')) == (0, 'The daemon has been stopped\n')
    assert _said(ros2('daemon', 'stop')) == (0, 'The daemon is not running\n')
    wait_for(lambda: not _daemon_processes(cli_env['ROS_DOMAIN_ID']), 10,
             "the stopped daemon's process to end")


def test_without_a_verb_it_prints_its_help(ros2):
    assert _said(ros2('daemon')) == (0, DAEMON_HELP)


def test_the_first_listing_starts_the_daemon_and_no_daemon_starts_none(ros2):
    ros2('daemon', 'stop')
    ros2('node', 'list', '--no-daemon')
    assert ros2('daemon', 'status').stdout == 'The daemon is not running\n'
    ros2('node', 'list')
    wait_for(lambda: ros2('daemon', 'status').stdout == 'The daemon is running\n', 10,
             'the daemon the first listing starts to run')


def test_the_daemons_graph_counts_its_own_node(ros2):
    """Nothing else runs in this module's domain: /rosout has one publisher, the
    daemon's own, as `ros2 topic info /rosout` says on Jazzy; its node is hidden."""
    ros2('daemon', 'start')
    assert _said(ros2('topic', 'info', '/rosout')) == (
        0, 'Type: rcl_interfaces/msg/Log\nPublisher count: 1\nSubscription count: 0\n')
    assert ros2('node', 'list').stdout == ''
    hidden = ros2('node', 'list', '-a').stdout.split()
    assert len(hidden) == 1 and hidden[0].startswith('/_ros2cli_daemon_'), hidden


def test_the_daemon_sees_a_node_started_after_it_and_describes_it(ros2, start_node):
    ros2('daemon', 'start')
    start_node('talker')
    wait_for(lambda: '/sensor_publisher' in ros2('node', 'list').stdout.split(), 15,
             'the daemon to list the new node')
    through_daemon = ros2('topic', 'info', '-v', '/chatter').stdout
    direct = ros2('topic', 'info', '-v', '/chatter', '--no-daemon').stdout

    def without_gids(text: str) -> list[str]:
        return [line for line in text.splitlines() if not line.startswith('GID: ')]
    assert 'Publisher count: 1' in through_daemon
    assert without_gids(through_daemon) == without_gids(direct)
    info = ros2('node', 'info', '/sensor_publisher')
    assert info.returncode == 0 and '    /chatter: std_msgs/msg/String' in info.stdout
