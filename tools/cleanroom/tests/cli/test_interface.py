"""`ros2 interface ...` in Jazzy's words (texts recorded from the Jazzy reference)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

SHARE = f'{sys.prefix}/share'

TWIST_STAMPED = """\
# A twist with reference coordinate frame and timestamp

std_msgs/Header header
\tbuiltin_interfaces/Time stamp
\t\tint32 sec
\t\tuint32 nanosec
\tstring frame_id
Twist twist
\tVector3  linear
\t\tfloat64 x
\t\tfloat64 y
\t\tfloat64 z
\tVector3  angular
\t\tfloat64 x
\t\tfloat64 y
\t\tfloat64 z
"""

STRING = """\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

string data
"""

SET_BOOL = """\
bool data # e.g. for hardware enabling / disabling
---
bool success   # indicate successful run of triggered service
string message # informational, e.g. for error messages
"""

POLYGON = """\
# A specification of a polygon where the first and last points are assumed to be connected

Point32[] points
\t#
\t#
\tfloat32 x
\tfloat32 y
\tfloat32 z
"""

POSE_WITH_COVARIANCE_NO_COMMENTS = """\
Pose pose
\tPoint position
\t\tfloat64 x
\t\tfloat64 y
\t\tfloat64 z
\tQuaternion orientation
\t\tfloat64 x 0
\t\tfloat64 y 0
\t\tfloat64 z 0
\t\tfloat64 w 1
float64[36] covariance
"""

GOAL_INFO_ALL_COMMENTS = """\
# Goal info (contains ID and timestamp).
GoalInfo goal_info
\t# Goal ID
\tunique_identifier_msgs/UUID goal_id
\t\t# A universally unique identifier (UUID).
\t\t#
\t\t#  http://en.wikipedia.org/wiki/Universally_unique_identifier
\t\t#  http://tools.ietf.org/html/rfc4122.html

\t\tuint8[16] uuid

\t# Time when the goal was accepted
\tbuiltin_interfaces/Time stamp
\t\t# This message communicates ROS Time defined here:
\t\t# https://design.ros2.org/articles/clock_and_time.html

\t\t# The seconds component, valid over all int32 values.
\t\tint32 sec

\t\t# The nanoseconds component, valid in the range [0, 1e9), to be added to the seconds component.
\t\t# e.g.
\t\t# The time -1.7 seconds is represented as {sec: -2, nanosec: 3e8}
\t\t# The time 1.7 seconds is represented as {sec: 1, nanosec: 7e8}
\t\tuint32 nanosec

# Action goal state-machine status.
int8 status
"""

SHOW_USAGE = 'usage: ros2 interface show [-h] [--all-comments | --no-comments] type\n'

INTERFACE_HELP = """\
usage: ros2 interface [-h]
                      Call `ros2 interface <command> -h` for more detailed
                      usage. ...

Show information about ROS interfaces

options:
  -h, --help            show this help message and exit

Commands:
  list      List all interface types available
  package   Output a list of available interface types within one package
  packages  Output a list of packages that provide interfaces
  proto     Output an interface prototype
  show      Output the interface definition

  Call `ros2 interface <command> -h` for more detailed usage.
"""

#: This environment's ros2 (the module fixture `ros2` runs it too).
ROS2 = str(Path(sys.executable).with_name('ros2'))


@pytest.fixture(scope='module')
def ros2i(ros2):
    def run(*args, **kwargs):
        return ros2(*args, env={'AMENT_PREFIX_PATH': sys.prefix, 'COLUMNS': '80'}, **kwargs)
    return run


@pytest.mark.parametrize(('name', 'expected'), [
    ('std_msgs/msg/String', STRING),
    ('geometry_msgs/msg/TwistStamped', TWIST_STAMPED),
    ('std_srvs/srv/SetBool', SET_BOOL),
    ('geometry_msgs/msg/Polygon', POLYGON),
])
def test_show_nests_definitions_without_their_comments(ros2i, name, expected):
    result = ros2i('interface', 'show', name)
    assert (result.returncode, result.stdout, result.stderr) == (0, expected, '')


def test_show_no_comments(ros2i):
    result = ros2i('interface', 'show', '--no-comments', 'geometry_msgs/msg/PoseWithCovariance')
    assert (result.returncode, result.stdout) == (0, POSE_WITH_COVARIANCE_NO_COMMENTS)
    result = ros2i('interface', 'show', '--no-comments', 'std_srvs/srv/SetBool')
    assert result.stdout == 'bool data #\n---\nbool success   #\nstring message #\n'


def test_show_all_comments(ros2i):
    result = ros2i('interface', 'show', '--all-comments', 'action_msgs/msg/GoalStatus')
    assert result.returncode == 0
    assert result.stdout.endswith(GOAL_INFO_ALL_COMMENTS)


def test_show_constants_stay_as_written(ros2i):
    out = ros2i('interface', 'show', 'sensor_msgs/msg/NavSatFix').stdout
    assert 'NavSatStatus status\n\t#\n\tint8 STATUS_UNKNOWN = -2        #\n' in out
    assert ('\tint8 status -2 #\n\tuint16 SERVICE_UNKNOWN = 0  #\n'
            '\tuint16 SERVICE_GPS =     1\n') in out


def test_show_reads_the_type_from_stdin(ros2i, cli_env):
    result = subprocess.run([ROS2, 'interface', 'show', '-'], input='std_msgs/msg/Bool\n',
                            env={**cli_env, 'AMENT_PREFIX_PATH': sys.prefix},
                            capture_output=True, text=True, timeout=30)
    assert (result.returncode, result.stdout.splitlines()[-1]) == (0, 'bool data')


@pytest.mark.parametrize(('name', 'error'), [
    ('std_msgs/String', "Invalid name 'std_msgs/String'. Expected three parts separated by '/'"),
    ('a/b/c/d', "Invalid name 'a/b/c/d'. Expected three parts separated by '/'"),
    ('/msg/String', "Invalid name '/msg/String'. Must not contain empty parts"),
    ('nosuch_pkg/msg/Foo', "Unknown package 'nosuch_pkg'"),
    ('std_msgs/msg/Nope', f"Could not find the interface '{SHARE}/std_msgs/msg/Nope.idl'"),
    ('std_msgs/srv/String', f"Could not find the interface '{SHARE}/std_msgs/srv/String.idl'"),
])
def test_show_errors(ros2i, name, error):
    result = ros2i('interface', 'show', name)
    assert (result.returncode, result.stdout, result.stderr) == (1, '', error + '\n')


def test_show_usage_errors(ros2i):
    result = ros2i('interface', 'show', '')
    assert (result.returncode, result.stderr) == (
        2, SHOW_USAGE + 'ros2 interface show: error: the passed value is empty\n')
    result = ros2i('interface', 'show', '--all-comments', '--no-comments', 'std_msgs/msg/Bool')
    assert (result.returncode, result.stderr) == (
        2, SHOW_USAGE + 'ros2 interface show: error: argument --no-comments: not allowed '
                        'with argument --all-comments\n')


def test_help(ros2i):
    assert ros2i('interface', '-h').stdout == INTERFACE_HELP
    assert ros2i('interface').stdout == INTERFACE_HELP


def test_list_sections_sorted(ros2i):
    lines = ros2i('interface', 'list').stdout.splitlines()
    assert lines[:3] == ['Messages:', '    action_msgs/msg/GoalInfo',
                         '    action_msgs/msg/GoalStatus']
    assert lines[-1] == 'Actions:'
    services = lines[lines.index('Services:') + 1:lines.index('Actions:')]
    assert services == sorted(services)
    assert '    std_srvs/srv/SetBool' in services
    result = ros2i('interface', 'list', '-s', '-a')
    assert result.stdout.splitlines()[0] == 'Services:'
    assert result.stdout.endswith(
        '    type_description_interfaces/srv/GetTypeDescription\nActions:\n')


def test_packages(ros2i):
    out = ros2i('interface', 'packages').stdout.splitlines()
    assert out[:3] == ['action_msgs', 'builtin_interfaces', 'geometry_msgs'] and out == sorted(out)
    services = ros2i('interface', 'packages', '-s').stdout.splitlines()
    assert 'std_srvs' in services and 'std_msgs' not in services
    # -m wins over -s, as in Jazzy
    assert ros2i('interface', 'packages', '-m', '-s').stdout == \
        ros2i('interface', 'packages', '-m').stdout
    assert ros2i('interface', 'packages', '-a').stdout == ''


def test_package(ros2i):
    result = ros2i('interface', 'package', 'std_srvs')
    assert result.returncode == 0
    # Jazzy prints them in (hash-randomised) set order
    assert sorted(result.stdout.splitlines()) == [
        'std_srvs/srv/Empty', 'std_srvs/srv/SetBool', 'std_srvs/srv/Trigger']
    assert ros2i('interface', 'package', '-m', 'std_srvs').stdout == ''
    result = ros2i('interface', 'package', 'nosuch')
    assert (result.returncode, result.stdout, result.stderr) == (
        1, '', "Unknown package 'nosuch'\n")


def test_proto(ros2i):
    result = ros2i('interface', 'proto', 'geometry_msgs/msg/Twist')
    assert (result.returncode, result.stdout) == (
        0, '"linear:\n  x: 0.0\n  y: 0.0\n  z: 0.0\nangular:\n  x: 0.0\n  y: 0.0\n  z: 0.0\n"\n')
    assert ros2i('interface', 'proto', 'std_msgs/msg/String').stdout == '"data: \'\'\n"\n'
    assert ros2i('interface', 'proto', 'std_srvs/srv/SetBool').stdout == '"data: false\n"\n'
    assert ros2i('interface', 'proto', '--no-quotes', 'std_msgs/msg/Empty').stdout == '{}\n\n'
