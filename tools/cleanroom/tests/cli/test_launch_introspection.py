"""`ros2 launch -p/--print` and `-d/--debug`, in the formats Jazzy printed.

The launch files are written to a temporary folder; nothing is started by
`-p`, and the `-d` case fails before starting any process.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

HERE = Path(__file__).parent
# conformance case 01_basic_nodes, whose `ros2 launch -p` output is recorded
BASIC_NODES = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='conf_pkg', executable='talker', name='sensor_publisher', output='screen'),
        Node(package='conf_pkg', executable='listener', name='data_processor', output='screen'),
    ])
"""
BASIC_NODES_PRINTED = re.escape(
    "├── ExecuteProcess(cmd=[ExecInPkg(pkg='conf_pkg', exec='talker'), '--ros-args', '-r', "
    "LocalVar('node name')], cwd=None, env=None, shell=False)\n"
    "└── ExecuteProcess(cmd=[ExecInPkg(pkg='conf_pkg', exec='listener'), '--ros-args', '-r', "
    "LocalVar('node name')], cwd=None, env=None, shell=False)\n")
DESCRIPTION_REPR = r'<launch\.launch_description\.LaunchDescription object at 0x[0-9a-f]+>\n'

NO_GENERATE = 'from launch import LaunchDescription\n'


@pytest.fixture
def launch_file(tmp_path: Path):
    def write(text: str, name: str = 'case.launch.py') -> str:
        path = tmp_path / name
        path.write_text(text)
        return str(path)
    return write


@pytest.mark.parametrize('flag', ['-p', '--print', '--print-description'])
def test_print_shows_the_description_tree_without_launching(ros2, launch_file, flag):
    result = ros2('launch', flag, launch_file(BASIC_NODES))
    assert (result.returncode, result.stderr) == (0, '')
    assert re.fullmatch(DESCRIPTION_REPR + BASIC_NODES_PRINTED, result.stdout), result.stdout


def test_print_names_cwd_env_and_shell_of_a_process(ros2, launch_file):
    """Observed on Jazzy: the cwd is quoted twice (`cwd=''/tmp''`)."""
    path = launch_file(
        'from launch import LaunchDescription\n'
        'from launch.actions import ExecuteProcess\n'
        'def generate_launch_description():\n'
        "    return LaunchDescription([ExecuteProcess(cmd=['ls', '-l'], cwd='/tmp',"
        " shell=True)])\n")
    result = ros2('launch', '-p', path)
    assert result.stdout.splitlines()[1] == \
        "└── ExecuteProcess(cmd=['ls', '-l'], cwd=''/tmp'', env=None, shell=True)"


def test_print_matches_jazzy_on_a_tour_of_entities(ros2):
    """print_tour.expected is Jazzy's `ros2 launch -p` output for print_tour.launch.py.

    Observed on Jazzy: any action but a process, LogInfo, EmitEvent and
    RegisterEventHandler is `Action('<its repr>')` (groups, includes and timers
    unexpanded); a Node is an ExecuteProcess with a bare '--ros-args'; an event
    handler shows its matcher text and its actions below it, in a tree whose
    last lines lose their '│'.  Only the addresses differ between runs.
    """
    result = ros2('launch', '-p', str(HERE / 'print_tour.launch.py'))
    assert (result.returncode, result.stderr) == (0, '')
    printed = re.sub(r'0x[0-9a-f]+', '0x…', result.stdout)
    assert printed.splitlines() == (HERE / 'print_tour.expected').read_text().splitlines()


def test_print_shows_a_launch_file_class_by_its_str(ros2, launch_file):
    """Observed on Jazzy: `Action(str(action))`, `EmitEvent(event=<the event's name>)`."""
    path = launch_file(
        'from launch import Action, Event, LaunchDescription\n'
        'from launch.actions import EmitEvent\n'
        'class Mine(Action):\n'
        "    def __str__(self):\n        return 'mine'\n"
        'class MyEvent(Event):\n'
        "    name = 'my.Event'\n"
        'def generate_launch_description():\n'
        '    return LaunchDescription([Mine(), EmitEvent(event=MyEvent()),'
        ' EmitEvent(event=Event())])\n')
    assert ros2('launch', '-p', path).stdout.splitlines()[1:] == [
        "├── Action('mine')",
        "├── EmitEvent(event='my.Event')",
        "└── EmitEvent(event='launch.Event')"]


def test_print_and_show_args_exclude_each_other(ros2, launch_file):
    result = ros2('launch', '-p', '-s', launch_file(BASIC_NODES))
    assert (result.returncode, result.stdout) == (2, '')
    assert result.stderr.startswith('usage: ros2 launch ')
    assert result.stderr.splitlines()[-1] == (
        'ros2 launch: error: argument -s/--show-args/--show-arguments: not allowed with '
        'argument -p/--print/--print-description')


def test_unknown_option_is_rejected_by_ros2(ros2, launch_file):
    result = ros2('launch', '--bogus', launch_file(BASIC_NODES))
    assert (result.returncode, result.stdout) == (2, '')
    assert result.stderr.splitlines() == [
        'usage: ros2 [-h] [--use-python-default-buffering]',
        '            Call `ros2 <command> -h` for more detailed usage. ...',
        'ros2: error: unrecognized arguments: --bogus']


@pytest.mark.parametrize('flag', ['-d', '--debug'])
def test_debug_sets_the_verbosity_and_logs_the_traceback(ros2, launch_file, flag):
    path = launch_file(NO_GENERATE)
    result = ros2('launch', flag, path)
    assert result.returncode == 1
    lines = result.stdout.splitlines()
    assert '[INFO] [launch]: Default logging verbosity is set to DEBUG' in lines
    assert '[DEBUG] [launch]: Traceback (most recent call last):' in lines
    errors = [line for line in lines if line.startswith('[ERROR] [launch]: ')]
    assert errors[0].startswith('[ERROR] [launch]: Caught exception in launch (see debug for '
                                'traceback): Caught multiple exceptions')
    assert lines.index('[DEBUG] [launch]: Traceback (most recent call last):') < \
        lines.index(errors[0])


def test_without_debug_there_is_no_traceback(ros2, launch_file):
    result = ros2('launch', launch_file(NO_GENERATE))
    assert result.returncode == 1
    assert '[INFO] [launch]: Default logging verbosity is set to INFO' in result.stdout
    assert 'Traceback' not in result.stdout + result.stderr
