"""labkit.launch / labkit.run: real launches of the snippets workspace.

`ros_env` (tests/conftest.py) is a student's terminal environment: the
workspace sourced and a private ROS domain, which this process shares.
"""
from __future__ import annotations

import labkit
import pytest
from labkit.commands import format_argument
from rclhelpers.processes import group_members

from .._polling import still_running

SYSTEM_NODES = ['/sensor_publisher', '/data_processor']


def test_launch_shows_the_command_and_finds_its_nodes(ros_env):
    with labkit.launch('my_robot_pkg', 'robot_system.launch.py', env=ros_env) as run:
        assert run.command == 'ros2 launch my_robot_pkg robot_system.launch.py'
        nodes = run.wait_for_nodes(SYSTEM_NODES)
        assert set(SYSTEM_NODES) <= set(nodes)
        line = run.wait_for_output(r'Publishing distance readings')
        assert line.startswith('[sensor_publisher-1] ')
        assert run.running
    assert run.returncode == 0
    assert 'process has finished cleanly' in run.output()
    assert run.lines == run.output().splitlines()
    # A terminal's Ctrl-C: each node got SIGINT once, from the group signal, and
    # the interactive launch sent none of its own (Jazzy's does without a terminal).
    assert "sending signal 'SIGINT'" not in run.output()


def test_a_started_command_has_a_terminal_as_stdin(ros_env):
    with labkit.start(['python3', '-c', 'import sys; print("tty", sys.stdin.isatty())'],
                      env=ros_env) as command:
        assert command.wait_for_output('^tty') == 'tty True'


def test_launch_arguments_become_name_value_pairs(ros_env):
    with labkit.launch('my_robot_pkg', 'robot_args.launch.py', robot_name='my_bot',
                       max_speed=1.5, sim_mode=False, env=ros_env) as run:
        assert run.command == ('ros2 launch my_robot_pkg robot_args.launch.py '
                               'robot_name:=my_bot max_speed:=1.5 sim_mode:=false')
        run.wait_for_nodes(['/robot_controller'])
        parameters = labkit.read_parameters('/robot_controller')
    assert parameters['robot_name'] == 'my_bot'
    assert parameters['max_linear_speed'] == 1.5


def test_format_argument():
    assert [format_argument(v) for v in (True, False, 2, 0.5, 'x', [1, 'a'])] == \
        ['true', 'false', '2', '0.5', 'x', '[1, a]']


def test_wait_for_nodes_timeout_names_missing_and_present_nodes(ros_env):
    run = labkit.launch('my_robot_pkg', 'robot_system.launch.py', env=ros_env)
    run.wait_for_nodes(SYSTEM_NODES)
    with pytest.raises(labkit.NodesNotFoundError) as caught:
        run.wait_for_nodes(['/sensor_publisher', 'robot_controller'], timeout=2)
    message = str(caught.value)
    assert message.startswith('Timed out after 2 s waiting for node /robot_controller from '
                              '`ros2 launch my_robot_pkg robot_system.launch.py`.')
    assert 'Nodes in the graph: /data_processor, /sensor_publisher.' in message
    assert 'Last lines of its output:\n' in message
    assert not run.running  # a failed wait stops the launch


def test_wait_for_nodes_reports_a_launch_that_died(ros_env):
    run = labkit.launch('my_robot_pkg', 'nope.launch.py', env=ros_env)
    with pytest.raises(labkit.ProcessExitedError) as caught:
        run.wait_for_nodes(['/sensor_publisher'], timeout=30)
    message = str(caught.value)
    assert message.startswith('`ros2 launch my_robot_pkg nope.launch.py` exited with code 1 '
                              'while waiting for node /sensor_publisher.')
    assert 'nope.launch.py' in message.split('Last lines of its output:\n')[1]


def test_stop_reaps_the_whole_process_group_and_is_idempotent(ros_env):
    run = labkit.launch('my_robot_pkg', 'robot_system.launch.py', env=ros_env)
    run.wait_for_nodes(SYSTEM_NODES)
    members = [proc.pid for proc in group_members(run.pid)]
    assert run.pid in members and len(members) >= 3  # the launch and its two nodes
    watchdog = run._watchdog.pid
    code = run.stop()
    assert code == 0
    assert still_running(members + [watchdog]) == []
    assert run.stop() == code
    assert repr(run).endswith(', exited with code 0>')


def test_stop_escalates_when_sigint_is_ignored(ros_env, tmp_path):
    script = tmp_path / 'stubborn.py'
    script.write_text('import signal, subprocess, sys, time\n'
                      'signal.signal(signal.SIGINT, signal.SIG_IGN)\n'
                      'subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"])\n'
                      'print("ready", flush=True)\n'
                      'time.sleep(600)\n')
    background = labkit.start(['python3', str(script)], env=ros_env)
    background.wait_for_output('ready')
    members = [proc.pid for proc in group_members(background.pid)]
    assert len(members) == 2
    assert background.stop(sigint_grace=0.5, sigterm_grace=2) == -15  # SIGTERM ended it
    assert still_running(members) == []


def test_run_builds_ros_args(ros_env):
    with labkit.run('my_robot_pkg', 'sensor_publisher', parameters={'publish_rate': 5.0},
                    name='front_sensor', env=ros_env) as node:
        assert node.command == ('ros2 run my_robot_pkg sensor_publisher --ros-args '
                                '-r __node:=front_sensor -p publish_rate:=5.0')
        node.wait_for_nodes(['/front_sensor'])
        assert labkit.read_parameters('/front_sensor')['publish_rate'] == 5.0
    assert node.returncode == 0


def test_stop_also_ends_children_that_outlive_the_command(ros_env, tmp_path):
    """The command dies of Ctrl-C; its child ignores it and is stopped afterwards."""
    script = tmp_path / 'parent.py'
    script.write_text('import subprocess, sys, time\n'
                      'child = subprocess.Popen([sys.executable, "-c", "import signal, time; '
                      'signal.signal(signal.SIGINT, signal.SIG_IGN); print(flush=True); '
                      'time.sleep(600)"], stdout=subprocess.PIPE)\n'
                      'child.stdout.readline()\n'
                      'print("ready", flush=True)\n'
                      'time.sleep(600)\n')
    background = labkit.start(['python3', str(script)], env=ros_env)
    background.wait_for_output('ready')
    members = [proc.pid for proc in group_members(background.pid)]
    assert len(members) == 2
    assert background.stop(sigint_grace=5, sigterm_grace=5) == -2  # Ctrl-C ended the command
    assert still_running(members) == []


def test_wait_returns_the_exit_code_of_a_command_that_ends_by_itself(ros_env):
    background = labkit.start(['python3', '-c', 'import sys; print("bye"); sys.exit(3)'],
                              env=ros_env)
    assert background.wait(timeout=60) == 3
    assert background.output() == 'bye'


def test_wait_stops_a_command_that_does_not_end_and_says_so(ros_env):
    background = labkit.start(['python3', '-c', 'import time; print("up", flush=True); '
                                               'time.sleep(600)'], env=ros_env)
    background.wait_for_output('up')
    with pytest.raises(labkit.LabkitError, match=r'still running after 0.5 s'):
        background.wait(timeout=0.5)
    assert not background.running
