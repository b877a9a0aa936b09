"""`ros2 extension_points` and `ros2 extensions` in Jazzy's words (recorded from the reference).

Both are hidden from `ros2 -h` (test_top_level.py).  The clean room derives its
lists from its own commands and their sub-verbs; they equal Jazzy's ros-base
lists because the clean room has the same commands and verbs.
"""
from __future__ import annotations

from ros2_cleanroom.cli import COMMANDS
from ros2_cleanroom.extension_registry import extension_points, extensions
from ros2_cleanroom.verbs.topic import build_parser as build_topic_parser

EXTENSION_POINTS_HELP = """\
usage: ros2 extension_points [-h] [--all] [--verbose]

List extension points

options:
  -h, --help     show this help message and exit
  --all, -a      Also show extension points which failed to be imported.
                 (prefixed with `- `)
  --verbose, -v  Show more information for each extension point
"""

EXTENSIONS_HELP = """\
usage: ros2 extensions [-h] [--all] [--verbose]

List extensions

options:
  -h, --help     show this help message and exit
  --all, -a      Also show extensions which failed to load or are
                 incompatible. (prefixed with `- `)
  --verbose, -v  Show more information for each extension
"""

EXTENSION_POINTS = """\
ros2action.verb: The extension point for 'action' verb extensions
ros2cli.command: The extension point for 'command' extensions
ros2cli.daemon.verb: The extension point for 'daemon' verb extensions
ros2component.verb: The extension point for 'node' verb extensions
ros2doctor.verb: The extension point for 'doctor' verb extensions
ros2interface.verb: Extension point for 'interface' verb extensions
ros2lifecycle.verb: The extension point for 'lifecycle' verb extensions
ros2multicast.verb: The extension point for 'msg' verb extensions
ros2node.verb: The extension point for 'node' verb extensions
ros2param.verb: The extension point for 'param' verb extensions
ros2pkg.verb: The extension point for 'pkg' verb extensions
ros2service.verb: The extension point for 'service' verb extensions
ros2topic.verb: The extension point for 'topic' verb extensions
"""

EXTENSIONS = """\
ros2action.verb
  info: Print information about an action
  list: Output a list of action names
  send_goal: Send an action goal
  type: Print a action's type
ros2cli.command
  action: Various action related sub-commands
  component: Various component related sub-commands
  daemon: Various daemon related sub-commands
  doctor: Check ROS setup and other potential issues
  extension_points: List extension points
  extensions: List extensions
  interface: Show information about ROS interfaces
  launch: Run a launch file
  lifecycle: Various lifecycle related sub-commands
  multicast: Various multicast related sub-commands
  node: Various node related sub-commands
  param: Various param related sub-commands
  pkg: Various package related sub-commands
  run: Run a package specific executable
  service: Various service related sub-commands
  topic: Various topic related sub-commands
  wtf: Use `wtf` as alias to `doctor`
ros2cli.daemon.verb
  start: Start the daemon if it isn't running
  status: Output the status of the daemon
  stop: Stop the daemon if it is running
ros2component.verb
  list: Output a list of running containers and components
  load: Load a component into a container node
  standalone: Run a component into its own standalone container node
  types: Output a list of components registered in the ament index
  unload: Unload a component from a container node
ros2doctor.verb
  hello: Check network connectivity between multiple hosts
ros2interface.verb
  list: List all interface types available
  package: Output a list of available interface types within one package
  packages: Output a list of packages that provide interfaces
  proto: Output an interface prototype
  show: Output the interface definition
ros2lifecycle.verb
  get: Get lifecycle state for one or more nodes
  list: Output a list of available transitions
  nodes: Output a list of nodes with lifecycle
  set: Trigger lifecycle state transition
ros2multicast.verb
  receive: Receive a single UDP multicast packet
  send: Send a single UDP multicast packet
ros2node.verb
  info: Output information about a node
  list: Output a list of available nodes
ros2param.verb
  delete: Delete parameter
  describe: Show descriptive information about declared parameters
  dump: Show all of the parameters of a node in a YAML file format
  get: Get parameter
  list: Output a list of available parameters
  load: Load parameter file for a node
  set: Set parameter
ros2pkg.verb
  create: Create a new ROS 2 package
  executables: Output a list of package specific executables
  list: Output a list of available packages
  prefix: Output the prefix path of a package
  xml: Output the XML of the package manifest or a specific tag
ros2service.verb
  call: Call a service
  echo: Echo a service
  find: Output a list of available services of a given type
  info: Print information about a service
  list: Output a list of available services
  type: Output a service's type
ros2topic.verb
  bw: Display bandwidth used by topic
  delay: Display delay of topic from timestamp in header
  echo: Output messages from a topic
  find: Output a list of available topics of a given type
  hz: Print the average publishing rate to screen
  info: Print information about a topic
  list: Output a list of available topics
  pub: Publish a message to a topic
  type: Print a topic's type
"""

VERBOSE_FAILURE = "AttributeError: 'EntryPoint' object has no attribute 'module_name'"


def test_extension_points_help(ros2):
    result = ros2('extension_points', '-h', env={'COLUMNS': '80'})
    assert (result.returncode, result.stdout) == (0, EXTENSION_POINTS_HELP)


def test_extensions_help(ros2):
    result = ros2('extensions', '-h', env={'COLUMNS': '80'})
    assert (result.returncode, result.stdout) == (0, EXTENSIONS_HELP)


def test_extension_points_are_jazzys(ros2):
    for args in ([], ['--all'], ['-a']):  # nothing fails to import: --all adds nothing
        result = ros2('extension_points', *args)
        assert (result.returncode, result.stdout, result.stderr) == (0, EXTENSION_POINTS, '')


def test_extensions_are_jazzys(ros2):
    for args in ([], ['--all'], ['-a']):
        result = ros2('extensions', *args)
        assert (result.returncode, result.stdout, result.stderr) == (0, EXTENSIONS, '')


def test_verbose_ends_after_the_first_extension_point_as_on_jazzy(ros2):
    for args in (['--verbose'], ['-v'], ['--all', '--verbose']):
        result = ros2('extension_points', *args)
        assert (result.returncode, result.stdout) == (1, EXTENSION_POINTS.splitlines(True)[0])
        assert result.stderr.startswith('Traceback (most recent call last):\n')
        assert result.stderr.splitlines()[-1] == VERBOSE_FAILURE


def test_verbose_ends_after_the_first_extension_as_on_jazzy(ros2):
    result = ros2('extensions', '-v')
    assert (result.returncode, result.stdout) == (
        1, 'ros2action.verb\n  info: Print information about an action\n')
    assert result.stderr.splitlines()[-1] == VERBOSE_FAILURE


def test_unknown_arguments_are_rejected_by_ros2(ros2):
    for command, argument in (('extensions', 'foo'), ('extension_points', '--bogus')):
        result = ros2(command, argument)
        assert (result.returncode, result.stdout) == (2, '')
        assert result.stderr.splitlines()[-1] == \
            f'ros2: error: unrecognized arguments: {argument}'


def test_the_lists_are_the_clean_rooms_own_commands_and_verbs():
    points = [entry_point.name for entry_point, _ in extension_points()]
    found = extensions()
    assert list(found) == points
    assert [entry_point.name for entry_point, _ in found['ros2cli.command']] == sorted(COMMANDS)
    for command in ('launch', 'run'):  # no sub-verbs: no extension point, as on Jazzy
        assert not any(command in name for name in points)
    topic_verbs = build_topic_parser().verbs.choices  # type: ignore[attr-defined]
    assert [entry_point.name for entry_point, _ in found['ros2topic.verb']] == sorted(topic_verbs)
