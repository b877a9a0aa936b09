"""`ros2 launch` with XML and YAML files: by package and name, by path, --show-args."""
from __future__ import annotations

import textwrap

ARGS_XML = """
<launch>
  <arg name="robot" default="rover" description="Robot name"/>
  <arg name="mode" default="sim">
    <choice value="sim"/>
    <choice value="real"/>
  </arg>
  <log message="robot=$(var robot) mode=$(var mode)"/>
</launch>
"""

ARGS_YAML = """
launch:
- arg: {name: robot, default: rover, description: Robot name}
- arg: {name: speed}
- log: {message: "robot=$(var robot) speed=$(var speed)"}
"""


def install(ros2, name: str, text: str):
    path = ros2.share / 'launch' / name
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def test_show_args_of_xml_by_package(ros2):
    install(ros2, 'args.launch.xml', ARGS_XML)
    result = ros2('launch', 'fe_pkg', 'args.launch.xml', '--show-args')
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        "Arguments (pass arguments as '<name>:=<value>'):", '',
        "    'robot':", '        Robot name', "        (default: 'rover')", '',
        "    'mode':", "        One of: ['sim', 'real']", "        (default: 'sim')"]


def test_show_args_of_yaml_by_path(ros2):
    path = install(ros2, 'args.launch.yaml', ARGS_YAML)
    result = ros2('launch', str(path), '-s')
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        "Arguments (pass arguments as '<name>:=<value>'):", '',
        "    'robot':", '        Robot name', "        (default: 'rover')", '',
        "    'speed':", '        no description given']


def test_launch_xml_by_package_with_arguments(ros2):
    install(ros2, 'args.launch.xml', ARGS_XML)
    result = ros2('launch', 'fe_pkg', 'args.launch.xml', 'robot:=scout', 'mode:=real')
    assert result.returncode == 0, result.stdout + result.stderr
    assert '[INFO] [launch.user]: robot=scout mode=real' in result.stdout.splitlines()


def test_launch_yaml_by_path(ros2):
    path = install(ros2, 'args.launch.yaml', ARGS_YAML)
    result = ros2('launch', str(path), 'speed:=2')
    assert result.returncode == 0, result.stdout + result.stderr
    assert '[INFO] [launch.user]: robot=rover speed=2' in result.stdout.splitlines()


def test_a_broken_xml_file_fails_with_every_loader_named(ros2):
    path = install(ros2, 'broken.launch.xml', '<launch><nodee/></launch>')
    result = ros2('launch', str(path))
    assert result.returncode == 1
    lines = result.stdout.splitlines()
    start = lines.index('[ERROR] [launch]: Caught exception in launch (see debug for traceback): '
                        'Caught multiple exceptions when trying to load file of format [xml]:')
    assert lines[start + 1:start + 3] == [
        ' - RuntimeError: Unrecognized entity of the type: nodee',
        ' - SyntaxError: invalid syntax (broken.launch.xml, line 1)']
