"""`ros2 pkg list|prefix|executables|xml` in Jazzy's words (recorded from the Jazzy reference)."""
from __future__ import annotations

import sys

import pytest

PREFIX = sys.prefix

STD_SRVS_XML = """\
<package format="3">
  <name>std_srvs</name>
  <version>5.3.6</version>
  <description>A package containing some standard service definitions.</description>

  <maintainer email="tfoote@openrobotics.org">Tully Foote</maintainer>

  <license>Apache License 2.0</license>

  <author email="dthomas@osrfoundation.org">Dirk Thomas</author>
  <author email="geoff@openrobotics.org">Geoffrey Biggs</author>
  <author email="michael@openrobotics.org">Michael Carroll</author>
  <author email="michel@ekumenlabs.com">Michel Hidalgo</author>

  <buildtool_depend>ament_cmake</buildtool_depend>

  <buildtool_depend>rosidl_default_generators</buildtool_depend>

  <exec_depend>rosidl_default_runtime</exec_depend>

  <test_depend>ament_lint_common</test_depend>

  <member_of_group>rosidl_interface_packages</member_of_group>

  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
"""

PREFIX_HELP = """\
usage: ros2 pkg prefix [-h] [--share] package_name

Output the prefix path of a package

positional arguments:
  package_name  The package name

options:
  -h, --help    show this help message and exit
  --share       Show share directory for the package
"""


@pytest.fixture(scope='module')
def pkg(ros2):
    def run(*args):
        return ros2('pkg', *args, env={'AMENT_PREFIX_PATH': PREFIX, 'COLUMNS': '80'})
    return run


def test_list_sorted(pkg):
    result = pkg('list')
    names = result.stdout.splitlines()
    assert result.returncode == 0 and names == sorted(names)
    assert names[:3] == ['action_msgs', 'ament_cmake', 'ament_cmake_core']
    assert 'std_msgs' in names


def test_prefix(pkg):
    assert (pkg('prefix', 'std_msgs').returncode, pkg('prefix', 'std_msgs').stdout) == \
        (0, PREFIX + '\n')
    assert pkg('prefix', '--share', 'std_msgs').stdout == f'{PREFIX}/share/std_msgs\n'
    result = pkg('prefix', 'nosuch')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', 'Package not found\n')
    assert pkg('prefix', '-h').stdout == PREFIX_HELP


def test_executables(pkg):
    assert pkg('executables', 'rosidl_adapter').stdout == (
        'rosidl_adapter action2idl.py\nrosidl_adapter msg2idl.py\nrosidl_adapter srv2idl.py\n')
    assert pkg('executables', '--full-path', 'rosidl_adapter').stdout == ''.join(
        f'{PREFIX}/lib/rosidl_adapter/{name}\n'
        for name in ('action2idl.py', 'msg2idl.py', 'srv2idl.py'))
    result = pkg('executables', 'std_msgs')
    assert (result.returncode, result.stdout) == (0, '')
    result = pkg('executables', 'nosuch')
    assert (result.returncode, result.stdout, result.stderr) == (
        1, '', "Package 'nosuch' not found\n")
    lines = pkg('executables').stdout.splitlines()
    assert lines[:2] == ['rosidl_adapter action2idl.py', 'rosidl_adapter msg2idl.py']
    assert lines == sorted(lines)


def test_xml(pkg):
    result = pkg('xml', 'std_srvs')
    assert (result.returncode, result.stdout) == (0, STD_SRVS_XML)
    assert pkg('xml', '-t', 'version', 'std_srvs').stdout == '5.3.6\n'
    assert pkg('xml', '-t', 'buildtool_depend', 'std_srvs').stdout == \
        'ament_cmake\nrosidl_default_generators\n'
    assert pkg('xml', '-t', 'export', 'std_srvs').stdout == '\n    \n'
    result = pkg('xml', '-t', 'nosuch', 'std_srvs')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', 'XML tag not found\n')
    result = pkg('xml', 'nosuch')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', 'Package not found\n')


def test_xml_drops_comments_as_jazzy(pkg):
    out = pkg('xml', 'rcl_interfaces').stdout
    assert '<ros1_bridge mapping_rules="mapping_rules.yaml" />' in out
    assert '<?xml' not in out
