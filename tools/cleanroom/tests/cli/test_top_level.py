"""`ros2` itself: its help lists every command of Jazzy's ros-base with ros2cli's one
top-level option, which it accepts before a command (recorded from the reference).
`extension_points` and `extensions` are hidden from the help, not from the list
of choices an unknown command gets."""
from __future__ import annotations

TOP_HELP = """\
usage: ros2 [-h] [--use-python-default-buffering]
            Call `ros2 <command> -h` for more detailed usage. ...

ros2 is an extensible command-line tool for ROS 2.

options:
  -h, --help            show this help message and exit
  --use-python-default-buffering
                        Do not force line buffering in stdout and instead use
                        the python default buffering, which might be affected
                        by PYTHONUNBUFFERED/-u and depends on whatever stdout
                        is interactive or not

Commands:
  action     Various action related sub-commands
  component  Various component related sub-commands
  daemon     Various daemon related sub-commands
  doctor     Check ROS setup and other potential issues
  interface  Show information about ROS interfaces
  launch     Run a launch file
  lifecycle  Various lifecycle related sub-commands
  multicast  Various multicast related sub-commands
  node       Various node related sub-commands
  param      Various param related sub-commands
  pkg        Various package related sub-commands
  run        Run a package specific executable
  service    Various service related sub-commands
  topic      Various topic related sub-commands
  wtf        Use `wtf` as alias to `doctor`

  Call `ros2 <command> -h` for more detailed usage.
"""


def test_help_is_jazzys(ros2):
    assert ros2('-h', env={'COLUMNS': '80'}).stdout == TOP_HELP
    assert ros2(env={'COLUMNS': '80'}).stdout == TOP_HELP  # no command: the same help


def test_the_buffering_option_comes_before_a_command(ros2):
    result = ros2('--use-python-default-buffering', 'daemon', '-h')
    assert (result.returncode, result.stdout.splitlines()[0]) == (0, 'usage: ros2 daemon [-h]'), \
        result.stderr


UNKNOWN_COMMAND = """\
usage: ros2 [-h] [--use-python-default-buffering]
            Call `ros2 <command> -h` for more detailed usage. ...
ros2: error: argument Call `ros2 <command> -h` for more detailed usage.: invalid choice: \
'nosuchverb' (choose from 'action', 'component', 'daemon', 'doctor', 'extension_points', \
'extensions', 'interface', 'launch', 'lifecycle', 'multicast', 'node', 'param', 'pkg', 'run', \
'service', 'topic', 'wtf')
"""


def test_an_unknown_command_lists_the_hidden_ones_too(ros2):
    result = ros2('nosuchverb', env={'COLUMNS': '80'})
    assert (result.returncode, result.stdout, result.stderr) == (2, '', UNKNOWN_COMMAND)
