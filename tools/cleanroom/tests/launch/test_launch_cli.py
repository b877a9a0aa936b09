"""`ros2 launch` and `ros2 run` against a package laid out like a colcon install."""
from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import psutil

ROS2 = str(Path(sys.executable).parent / 'ros2')  # the ros2 of this environment

SHOW_ARGS = """Arguments (pass arguments as '<name>:=<value>'):

    'speed':
        Top speed
        in m/s
        (default: '1.5')

    'mode':
        One of: ['a', 'b']

    'name':
        no description given
        (default: 'bot_' + LaunchConfig('mode'))
"""


def test_show_args(ros2, fake_prefix):
    result = ros2('launch', 'cr_pkg', 'args.launch.py', '--show-args')
    assert (result.returncode, result.stdout, result.stderr) == (0, SHOW_ARGS, '')
    path = str(fake_prefix / 'share/cr_pkg/launch/args.launch.py')
    assert ros2('launch', path, '-s').stdout == SHOW_ARGS


def test_launch_with_arguments_by_package_and_by_path(ros2, fake_prefix):
    result = ros2('launch', 'cr_pkg', 'args.launch.py', 'mode:=b', 'speed:=3')
    assert result.returncode == 0
    assert '[INFO] [launch.user]: speed=3 mode=b name=bot_b' in result.stdout.splitlines()
    path = str(fake_prefix / 'share/cr_pkg/launch/args.launch.py')
    result = ros2('launch', path, 'mode:=a')
    assert '[INFO] [launch.user]: speed=1.5 mode=a name=bot_a' in result.stdout.splitlines()


def test_launch_errors(ros2, fake_prefix):
    missing = ros2('launch', 'cr_pkg', 'args.launch.py')
    assert missing.returncode == 1
    assert missing.stdout.splitlines()[-1] == (
        '[ERROR] [launch]: Caught exception in launch (see debug for traceback): Included '
        "launch description missing required argument 'mode' (description: 'One of: "
        "['a', 'b']'), given: []")
    choice = ros2('launch', 'cr_pkg', 'args.launch.py', 'mode:=c')
    assert choice.returncode == 1
    assert 'Argument "mode" provided value "c" is not valid.' in choice.stdout
    nope = ros2('launch', 'cr_pkg', 'nope.launch.py')
    assert (nope.returncode, nope.stdout) == (1, '')
    assert nope.stderr == (f"file 'nope.launch.py' was not found in the share directory of "
                           f"package 'cr_pkg' which is at '{fake_prefix}/share/cr_pkg'\n")
    no_pkg = ros2('launch', 'no_pkg', 'x.launch.py')
    assert no_pkg.returncode == 1
    assert no_pkg.stderr == (f"Package 'no_pkg' not found: \"package 'no_pkg' not found, "
                             f"searching: ['{fake_prefix}']\"\n")
    malformed = ros2('launch', 'cr_pkg', 'args.launch.py', 'mode:=a', 'oops')
    assert (malformed.returncode, malformed.stdout) == (1, '')
    assert malformed.stderr == ("malformed launch argument 'oops', expected format "
                                "'<name>:=<value>'\n")


def test_print_description(ros2):
    """Observed on Jazzy for args.launch.py: arguments are opaque `Action('<repr>')` lines."""
    result = ros2('launch', 'cr_pkg', 'args.launch.py', '--print')
    assert result.returncode == 0
    declared = ("├── Action('<launch.actions.declare_launch_argument.DeclareLaunchArgument "
                "object at 0x…>')")
    assert re.sub(r'0x[0-9a-f]+', '0x…', result.stdout).splitlines()[1:] == [
        declared, declared, declared,
        "└── LogInfo('speed=' + LaunchConfig('speed') + ' mode=' + LaunchConfig('mode') + "
        "' name=' + LaunchConfig('name'))"]


def test_show_all_subprocesses_output(ros2, tmp_path):
    launch_file = tmp_path / 'quiet.launch.py'
    launch_file.write_text(
        'from launch import LaunchDescription\n'
        'from launch.actions import ExecuteProcess\n'
        'def generate_launch_description():\n'
        "    return LaunchDescription([ExecuteProcess(cmd=['echo', 'QUIET'], name='q')])\n")
    assert '[q-1] QUIET' not in ros2('launch', str(launch_file)).stdout
    assert '[q-1] QUIET' in ros2('launch', str(launch_file), '-a').stdout.splitlines()


def test_a_python_launch_file_is_loaded_as_jazzy_loads_it(cli_env, tmp_path):
    # Observed on the reference: the module is `python_launch_file`, loaded by Python's
    # SourceFileLoader from the path as given, not in sys.modules, and its bytecode is
    # written to __pycache__/ next to the file (unless PYTHONDONTWRITEBYTECODE is set).
    (tmp_path / 'probe.launch.py').write_text(
        'import sys\n'
        'from launch import LaunchDescription\n'
        'print(__name__, __file__, type(__loader__).__name__, __name__ in sys.modules)\n'
        'def generate_launch_description():\n'
        '    return LaunchDescription([])\n')
    env = {k: v for k, v in cli_env.items() if k != 'PYTHONDONTWRITEBYTECODE'}
    result = subprocess.run([ROS2, 'launch', './probe.launch.py'], cwd=tmp_path, env=env,
                            capture_output=True, text=True, stdin=subprocess.DEVNULL,
                            timeout=30)
    assert 'python_launch_file ./probe.launch.py SourceFileLoader False' in \
        result.stdout.splitlines()
    assert [p.name for p in (tmp_path / '__pycache__').iterdir()] == \
        [f'probe.launch.{sys.implementation.cache_tag}.pyc']


def test_launch_prefix(ros2, tmp_path):
    launch_file = tmp_path / 'prefixed.launch.py'
    launch_file.write_text(
        'from launch import LaunchDescription\n'
        'from launch.actions import ExecuteProcess\n'
        'def generate_launch_description():\n'
        "    return LaunchDescription([ExecuteProcess(cmd=['payload'], name='p',"
        " output='screen')])\n")
    result = ros2('launch', str(launch_file), '--launch-prefix', 'echo PREFIX')
    assert '[p-1] PREFIX payload' in result.stdout.splitlines()


def test_run_passes_arguments_and_prefix(ros2):
    result = ros2('run', 'cr_pkg', 'echo_args', 'a', 'b c', '--ros-args', '-r', 'x:=y')
    assert (result.returncode, result.stdout) == (0, 'args: a b c --ros-args -r x:=y\n')
    prefixed = ros2('run', '--prefix', 'echo PRE', 'cr_pkg', 'echo_args', 'z')
    assert prefixed.stdout.startswith('PRE ') and prefixed.stdout.rstrip().endswith(
        '/lib/cr_pkg/echo_args z')


def test_run_errors_and_exit_codes(ros2):
    failed = ros2('run', 'cr_pkg', 'exit_with', '3')
    assert (failed.returncode, failed.stdout) == (3, '[ros2run]: Process exited with failure 3\n')
    assert (ros2('run', 'cr_pkg', 'exit_with', '0').returncode) == 0
    no_exe = ros2('run', 'cr_pkg', 'nope')
    assert (no_exe.returncode, no_exe.stderr) == (1, 'No executable found\n')
    no_pkg = ros2('run', 'no_pkg', 'talker')
    assert (no_pkg.returncode, no_pkg.stderr) == (1, "Package 'no_pkg' not found\n")


def _start_in_own_group(cli_env: dict, *args: str) -> subprocess.Popen:
    """Start `ros2 ARGS` as a terminal would run it: its own process group."""
    return subprocess.Popen([ROS2, *args], env=cli_env, stdout=subprocess.PIPE, text=True,
                            stdin=subprocess.DEVNULL, start_new_session=True)


def test_run_waits_for_the_child_after_ctrl_c(cli_env):
    """Ctrl-C goes to the whole group; ros2 run itself must not die or forward it."""
    proc = _start_in_own_group(cli_env, 'run', 'cr_pkg', 'wait_for_signal')
    try:
        # 'ready' comes after both traps are set; ros2 run's own handler was set
        # before it started the child
        assert proc.stdout.readline() == 'ready\n'
        os.killpg(proc.pid, signal.SIGINT)
        out, _ = proc.communicate(timeout=10)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
    assert (proc.returncode, out) == (0, 'got INT\n')


def _signals_taken(pid: int, guard: float = 10.0) -> None:
    """Wait until ``pid`` has no signal pending: delivered, its handler has run (ros2 run
    waits in waitpid, which the signal interrupts; Python runs the handler right there)."""
    status = Path(f'/proc/{pid}/status')
    deadline = time.monotonic() + guard  # a hang guard, not a speed limit
    while any(int(line.split()[1], 16) for line in status.read_text().splitlines()
              if line.startswith(('SigPnd:', 'ShdPnd:'))):
        assert time.monotonic() < deadline, status.read_text()
        time.sleep(0.01)


def test_run_neither_dies_of_sigint_nor_forwards_it(cli_env):
    """SIGINT to ros2 run alone: it keeps waiting, and the child hears nothing of it;
    the child's own end (SIGTERM here) is then ros2 run's exit code, 0."""
    proc = _start_in_own_group(cli_env, 'run', 'cr_pkg', 'wait_for_signal')
    try:
        assert proc.stdout.readline() == 'ready\n'
        child = psutil.Process(proc.pid).children()[0]
        proc.send_signal(signal.SIGINT)  # to ros2 run only
        _signals_taken(proc.pid)
        child.send_signal(signal.SIGTERM)
        out, _ = proc.communicate(timeout=10)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
    assert (proc.returncode, out) == (0, 'got TERM\n')


def test_a_killed_run_takes_its_child_along(cli_env):
    """The death signal (SIGTERM) ends the child when ros2 run is killed."""
    proc = _start_in_own_group(cli_env, 'run', 'cr_pkg', 'wait_for_signal')
    try:
        assert proc.stdout.readline() == 'ready\n'
        child = psutil.Process(proc.pid).children()[0]
        proc.kill()
        out, _ = proc.communicate(timeout=10)
        _gone, alive = psutil.wait_procs([child], timeout=5)
        assert not alive
        assert out == 'got TERM\n'
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()


def test_choices_are_appended_to_a_given_description():
    """As Jazzy's --show-args shows them (observed: even an empty description gets them)."""
    from launch.actions import DeclareLaunchArgument

    def described(**given):
        return DeclareLaunchArgument('x', default_value='true', choices=['true', 'false'],
                                     **given).description

    assert described(description='Start it') == "Start it. Valid choices are: ['true', 'false']"
    assert described() == "One of: ['true', 'false']"
    assert described(description='') == ". Valid choices are: ['true', 'false']"
    assert DeclareLaunchArgument('y', description='Plain').description == 'Plain'
