"""`ros2 param describe|delete|load` against running nodes, with the texts, streams
and exit codes Jazzy's ros2 gave for the same nodes and files (issue #21)."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from _polling import wait_for
from ros2_cleanroom.param_file import flatten, read_parameter_file, to_parameter_value
from ros2_cleanroom.param_values import describe

EXTRA_NODES = str(Path(__file__).with_name('extra_nodes.py'))
SAMPLE_NODES = str(Path(__file__).with_name('sample_nodes.py'))

PARAM_HELP = """\
usage: ros2 param [-h]
                  Call `ros2 param <command> -h` for more detailed usage. ...

Various param related sub-commands

options:
  -h, --help            show this help message and exit

Commands:
  delete    Delete parameter
  describe  Show descriptive information about declared parameters
  dump      Show all of the parameters of a node in a YAML file format
  get       Get parameter
  list      Output a list of available parameters
  load      Load parameter file for a node
  set       Set parameter

  Call `ros2 param <command> -h` for more detailed usage.
"""

DESCRIBE_HELP = """\
usage: ros2 param describe [-h] [--spin-time SPIN_TIME] [-s] [--no-daemon]
                           [--include-hidden-nodes] [--timeout N]
                           node_name parameter_names [parameter_names ...]

Show descriptive information about declared parameters

positional arguments:
  node_name             Name of the ROS node
  parameter_names       Names of the parameters

options:
  -h, --help            show this help message and exit
  --spin-time SPIN_TIME
                        Spin time in seconds to wait for discovery (only
                        applies when not using an already running daemon)
  -s, --use-sim-time    Enable ROS simulation time
  --no-daemon           Do not spawn nor use an already running daemon
  --include-hidden-nodes
                        Consider hidden nodes as well
  --timeout N           Wait for N seconds until node becomes available
                        (default 1 sec)
"""

DELETE_HELP = """\
usage: ros2 param delete [-h] [--spin-time SPIN_TIME] [-s] [--no-daemon]
                         [--include-hidden-nodes] [--timeout N]
                         node_name parameter_name

Delete parameter

positional arguments:
  node_name             Name of the ROS node
  parameter_name        Name of the parameter

options:
  -h, --help            show this help message and exit
  --spin-time SPIN_TIME
                        Spin time in seconds to wait for discovery (only
                        applies when not using an already running daemon)
  -s, --use-sim-time    Enable ROS simulation time
  --no-daemon           Do not spawn nor use an already running daemon
  --include-hidden-nodes
                        Consider hidden nodes as well
  --timeout N           Wait for N seconds until node becomes available
                        (default 1 sec)
"""

LOAD_HELP = """\
usage: ros2 param load [-h] [--spin-time SPIN_TIME] [-s] [--no-daemon]
                       [--include-hidden-nodes] [--no-use-wildcard]
                       [--timeout N]
                       node_name parameter_file

Load parameter file for a node

positional arguments:
  node_name             Name of the ROS node
  parameter_file        Parameter file

options:
  -h, --help            show this help message and exit
  --spin-time SPIN_TIME
                        Spin time in seconds to wait for discovery (only
                        applies when not using an already running daemon)
  -s, --use-sim-time    Enable ROS simulation time
  --no-daemon           Do not spawn nor use an already running daemon
  --include-hidden-nodes
                        Consider hidden nodes as well
  --no-use-wildcard     Do not load parameters in the '/**' namespace into the
                        node
  --timeout N           Wait for N seconds until node becomes available
                        (default 1 sec)
"""

DESCRIBED = """\
Parameter name: speed
  Type: double
  Description: Top speed in m/s
  Constraints:
    Min value: 0.0
    Max value: 3.0
    Step: 0.5
Parameter name: count
  Type: integer
  Description: How many
  Constraints:
    Min value: 0
    Max value: 10
    Step: 1
    Additional constraints: Only odd numbers
Parameter name: frame
  Type: string
  Description: Fixed frame
  Constraints:
    Read only: true
Parameter name: anything
  Type: integer
  Constraints:
Parameter name: unset
  Type: integer
  Description: No default
  Constraints:
Parameter name: names
  Type: string array
  Constraints:
Parameter name: flags
  Type: boolean array
  Constraints:
Parameter name: ints
  Type: integer array
  Constraints:
Parameter name: blob
  Type: byte array
  Constraints:
"""

# A zero step is left out; a dynamically typed parameter without a value has no type.
COMBO_DYN = """\
Parameter name: combo
  Type: integer
  Description: d
  Constraints:
    Read only: true
    Min value: -1
    Max value: 4
    Additional constraints: ac
Parameter name: dyn
  Type: not set
  Constraints:
"""

UNDECLARED = 'Invalid access to undeclared parameter(s): []'


@pytest.fixture(scope='module')
def nodes(cli_env: dict[str, str]) -> Iterator[Callable[..., None]]:
    """`nodes(script, kind, *ros_args)`: start a node, up when this returns; all of them
    are stopped (SIGINT, then SIGKILL, process group) when the module ends."""
    started: list[subprocess.Popen] = []

    def start(script: str, kind: str, *ros_args: str) -> None:
        proc = subprocess.Popen([sys.executable, script, kind, *ros_args], env=cli_env,
                                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                start_new_session=True)
        started.append(proc)
        assert proc.stdout.readline().startswith('ready '), f'{kind} did not start'

    try:
        yield start
    finally:
        for proc in started:
            for sig in (signal.SIGINT, signal.SIGKILL):
                if proc.poll() is None:
                    os.killpg(proc.pid, sig)
                    try:
                        proc.wait(timeout=5)
                    except subprocess.TimeoutExpired:
                        continue
            proc.wait()


@pytest.fixture(scope='module')
def graph(nodes: Callable[..., None],
          ros2: Callable[..., subprocess.CompletedProcess]) -> None:
    """The module's nodes: /described, /open, /layered and /layered_b (its copy),
    each discovered and answering its parameter services (a node prints `ready`
    before it spins)."""
    nodes(EXTRA_NODES, 'described')
    nodes(EXTRA_NODES, 'open')
    nodes(SAMPLE_NODES, 'layered')
    nodes(SAMPLE_NODES, 'layered', '--ros-args', '-r', '__node:=layered_b')
    listed = {'/described:', '/open:', '/layered:', '/layered_b:'}
    wait_for(lambda: listed <= set(ros2('param', 'list').stdout.splitlines()), 15,
             'every node of the module to answer `ros2 param list` with its parameters')


@pytest.mark.parametrize(('args', 'expected'), [
    (('param', '-h'), PARAM_HELP),
    (('param', 'describe', '-h'), DESCRIBE_HELP),
    (('param', 'delete', '-h'), DELETE_HELP),
    (('param', 'load', '-h'), LOAD_HELP),
])
def test_help_is_jazzys(ros2, args, expected):
    result = ros2(*args, env={'COLUMNS': '80'})
    assert (result.stdout, result.returncode) == (expected, 0)


def test_missing_arguments_are_usage_errors(ros2):
    result = ros2('param', 'describe', '/described', env={'COLUMNS': '80'})
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == (
        'ros2 param describe: error: the following arguments are required: parameter_names')


def test_describe_every_part_of_a_descriptor(ros2, graph):
    result = ros2('param', 'describe', '/described', 'speed', 'count', 'frame', 'anything',
                  'unset', 'names', 'flags', 'ints', 'blob')
    assert (result.stdout, result.stderr, result.returncode) == (DESCRIBED, '', 0)


def test_describe_zero_step_and_untyped(ros2, graph):
    result = ros2('param', 'describe', 'described', 'combo', 'dyn')
    assert (result.stdout, result.returncode) == (COMBO_DYN, 0)


def test_describe_an_undeclared_name_prints_nothing(ros2, graph):
    # one undeclared name and the node describes none of them; still exit 0
    result = ros2('param', 'describe', '/described', 'speed', 'nope')
    assert (result.stdout, result.stderr, result.returncode) == ('', '', 0)


def test_describe_undeclared_on_a_node_that_allows_them(ros2, graph):
    result = ros2('param', 'describe', '/open', 'declared', 'undeclared_x')
    assert result.stdout == ('Parameter name: declared\n  Type: integer\n  Constraints:\n'
                             'Parameter name: \n  Type: not set\n  Constraints:\n')


@pytest.mark.parametrize('verb', [('describe', 'x'), ('delete', 'x'), ('load', 'missing.yaml')])
def test_unknown_node(ros2, graph, verb):
    result = ros2('param', verb[0], '/nope', verb[1], '--spin-time', '1')
    assert (result.stdout, result.stderr, result.returncode) == ('', 'Node not found\n', 1)


@pytest.mark.parametrize(('node', 'name', 'reason'), [
    ('/layered', 'level', 'Static parameter cannot be undeclared'),
    ('/open', 'declared', 'Static parameter cannot be undeclared'),
    ('/open', 'fixed', 'Trying to set a read-only parameter: fixed.'),
    ('/layered', 'nope', UNDECLARED),
])
def test_delete_refused_is_reported_but_exits_0(ros2, graph, node, name, reason):
    result = ros2('param', 'delete', node, name)
    assert (result.stdout, result.stderr, result.returncode) == (
        '', f'Deleting parameter failed: {reason}\n', 0)


def test_delete_dynamically_typed(ros2, graph):
    result = ros2('param', 'delete', '/described', 'anything')
    assert (result.stdout, result.stderr, result.returncode) == (
        'Deleted parameter successfully\n', '', 0)
    again = ros2('param', 'delete', '/described', 'anything')
    assert again.stderr == f'Deleting parameter failed: {UNDECLARED}\n'


def _write(tmp_path: Path, text: str, name: str = 'params.yaml') -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_load_sets_each_parameter(ros2, graph, tmp_path):
    path = _write(tmp_path, '/layered:\n  ros__parameters:\n    level: 7\n    label: loaded\n')
    result = ros2('param', 'load', '/layered', path)
    assert (result.stdout, result.stderr, result.returncode) == (
        'Set parameter level successful\nSet parameter label successful\n', '', 0)
    assert ros2('param', 'get', '/layered', 'level').stdout == 'Integer value is: 7\n'


WILDCARD_FILE = ('/**:\n  ros__parameters:\n    level: 9\n'
                 '/layered_b:\n  ros__parameters:\n    label: second\n    nope: 3\n')


def test_load_wildcard_and_refusals(ros2, graph, tmp_path):
    path = _write(tmp_path, WILDCARD_FILE)
    result = ros2('param', 'load', '/layered_b', path)
    assert (result.stdout, result.stderr, result.returncode) == (
        'Set parameter level successful\nSet parameter label successful\n',
        f'Set parameter nope failed: {UNDECLARED}\n', 0)
    result = ros2('param', 'load', '/layered_b', path, '--no-use-wildcard')
    assert (result.stdout, result.stderr) == (
        'Set parameter label successful\n', f'Set parameter nope failed: {UNDECLARED}\n')


def test_load_every_node_of_the_file_applies(ros2, graph, tmp_path):
    # the file's node names are not matched against the target: all of them load
    path = _write(tmp_path, 'layered:\n  ros__parameters:\n    level: 11\n'
                            '/open:\n  ros__parameters:\n    fixed: 6\n    combo: 3\n'
                            '    newone: 1.5\n    nested:\n      a: 1\n      b: [1, 2]\n')
    result = ros2('param', 'load', '/open', path)
    assert result.stdout == ('Set parameter level successful\nSet parameter newone successful\n'
                             'Set parameter nested.a successful\n'
                             'Set parameter nested.b successful\n')
    assert result.stderr == ('Set parameter fixed failed: Trying to set a read-only parameter: '
                             'fixed.\nSet parameter combo failed: Trying to set a read-only '
                             'parameter: combo.\n')
    assert result.returncode == 0


def test_load_types_values_as_param_set_does(ros2, graph, tmp_path):
    path = _write(tmp_path, '/open:\n  ros__parameters:\n    m1: [1, a]\n    m2: []\n'
                            '    m3: null\n    m4: "7"\n    m5: 1e3\n    m6: [1, 2.5]\n'
                            '    m8: "yes"\n')
    assert ros2('param', 'load', '/open', path).returncode == 0
    expected = {'m1': "String value is: [1, 'a']", 'm2': 'Boolean values are: []',
                'm3': 'String value is: None', 'm4': 'Integer value is: 7',
                'm5': 'String value is: 1e3', 'm6': 'String value is: [1, 2.5]',
                'm8': 'Boolean value is: True'}
    for name, line in expected.items():
        assert ros2('param', 'get', '/open', name).stdout == line + '\n', name


def test_load_wrong_type_is_refused(ros2, graph, tmp_path):
    path = _write(tmp_path, '/layered:\n  ros__parameters:\n    label: []\n    level: null\n')
    result = ros2('param', 'load', '/layered', path)
    assert (result.stdout, result.returncode) == ('', 0)
    assert result.stderr == (
        "Set parameter label failed: Wrong parameter type, expected 'Type.STRING' got "
        "'Type.BOOL_ARRAY'\n"
        "Set parameter level failed: Wrong parameter type, expected 'Type.INTEGER' got "
        "'Type.STRING'\n")


@pytest.mark.parametrize(('text', 'message'), [
    ('/layered:\n  level: 3\n', 'YAML file is not a valid ROS parameter file for node /layered'),
    ('/other:\n  level: 3\n', 'YAML file is not a valid ROS parameter file for node /other'),
])
def test_load_not_a_parameter_file(ros2, graph, tmp_path, text, message):
    result = ros2('param', 'load', '/layered', _write(tmp_path, text))
    assert (result.stdout, result.stderr, result.returncode) == ('', message + '\n', 1)


@pytest.mark.parametrize(('text', 'last_line'), [
    (None, "FileNotFoundError: [Errno 2] No such file or directory: '{path}'"),
    ('', "TypeError: argument of type 'NoneType' is not iterable"),
    ('[1, 2]\n', "AttributeError: 'list' object has no attribute 'keys'"),
    ('just a string\n', "AttributeError: 'str' object has no attribute 'keys'"),
    ('/**:\n  ros__parameters: 5\n', "TypeError: 'int' object is not iterable"),
    ('/layered:\n  ros__parameters:\n    level: [1\n', "expected ',' or ']', but got "
                                                      "'<stream end>'"),
])
def test_load_unreadable_file_ends_in_a_traceback(ros2, graph, tmp_path, text, last_line):
    path = str(tmp_path / 'missing.yaml') if text is None else _write(tmp_path, text)
    result = ros2('param', 'load', '/layered', path)
    lines = result.stderr.splitlines()
    assert result.returncode == 1
    assert lines[0] == 'Traceback (most recent call last):'
    assert last_line.format(path=path) in lines[-2:]


def test_parameter_file_without_ros():
    assert flatten({'a': {'b': 1, 'c': {'d': [1]}}, 'e': 2}) == {'a.b': 1, 'a.c.d': [1], 'e': 2}
    assert describe(to_parameter_value([])) == 'Boolean values are: []'
    assert describe(to_parameter_value(None)) == 'String value is: None'


def test_wildcard_comes_first_and_the_node_wins(tmp_path):
    path = _write(tmp_path, '/layered:\n  ros__parameters:\n    level: 1\n'
                            '/**:\n  ros__parameters:\n    level: 2\n    label: wild\n')
    assert list(read_parameter_file(path).items()) == [('level', 1), ('label', 'wild')]
    assert read_parameter_file(path, use_wildcard=False) == {'level': 1}
