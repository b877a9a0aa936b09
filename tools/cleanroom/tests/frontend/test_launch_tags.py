"""The tags of `launch` in XML and YAML files, run in a LaunchService; includes both ways."""
from __future__ import annotations

import io
import xml.etree.ElementTree as ET

from launch.actions import (
    AppendEnvironmentVariable,
    ExecuteProcess,
    GroupAction,
    SetEnvironmentVariable,
    Shutdown,
    UnsetLaunchConfiguration,
)
from launch.frontend import Parser
from launch.launch_description_sources import (
    FrontendLaunchDescriptionSource,
    get_launch_description_from_any_launch_file,
)
from launch.substitutions import TextSubstitution
from launch_xml import Entity as XMLEntity
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource


def parse_xml_action(text: str):
    return Parser().parse_action(XMLEntity(ET.parse(io.StringIO(text)).getroot()))


def texts(substitutions) -> list[str]:
    assert all(isinstance(s, TextSubstitution) for s in substitutions), substitutions
    return [s.text for s in substitutions]


def test_args_defaults_and_command_line(write, run_file):
    path = write('a.launch.xml', """
        <launch>
          <arg name="robot" default="rover" description="Robot name"/>
          <arg name="speed" default="1.5"/>
          <log message="robot=$(var robot) speed=$(var speed)"/>
        </launch>""")
    assert run_file(path).user_lines() == ['robot=rover speed=1.5']
    assert run_file(path, 'robot:=scout').user_lines() == ['robot=scout speed=1.5']
    arguments = get_launch_description_from_any_launch_file(str(path)).get_launch_arguments()
    assert [(a.name, a.description) for a in arguments] == [
        ('robot', 'Robot name'), ('speed', 'no description given')]


def test_required_arg_and_choices(write, run_file):
    path = write('a.launch.yaml', """
        launch:
        - arg: {name: mode, choice: [{value: sim}, {value: real}]}
        - log: {message: "mode $(var mode)"}""")
    arguments = get_launch_description_from_any_launch_file(str(path)).get_launch_arguments()
    assert arguments[0].choices == ['sim', 'real'] and arguments[0].default_value is None
    assert run_file(path, 'mode:=real').user_lines() == ['mode real']


def test_if_unless_and_eval(write, run_file):
    path = write('c.launch.xml', """
        <launch>
          <arg name="on" default="true"/>
          <log message="if" if="$(var on)"/>
          <log message="unless" unless="$(var on)"/>
          <log message="eval" if="$(eval '&quot;$(var on)&quot; == &quot;true&quot;')"/>
        </launch>""")
    assert run_file(path).user_lines() == ['if', 'eval']
    assert run_file(path, 'on:=False').user_lines() == ['unless']


def test_groups_scope_let_and_unscoped_groups_leak(write, run_file):
    for name, text in (('g.launch.xml', """
        <launch>
          <let name="level" value="outer"/>
          <group><let name="level" value="inner"/><log message="in: $(var level)"/></group>
          <log message="scoped: $(var level)"/>
          <group scoped="false"><let name="level" value="leaked"/></group>
          <log message="unscoped: $(var level)"/>
          <group scoped="maybe"><let name="level" value="maybe"/></group>
          <log message="maybe: $(var level)"/>
        </launch>"""), ('g.launch.yaml', """
        launch:
        - let: {name: level, value: outer}
        - group:
            children:
            - let: {name: level, value: inner}
            - log: {message: "in: $(var level)"}
        - log: {message: "scoped: $(var level)"}
        - group: {scoped: false, children: [{let: {name: level, value: leaked}}]}
        - log: {message: "unscoped: $(var level)"}
        - group: {scoped: maybe, children: [{let: {name: level, value: maybe}}]}
        - log: {message: "maybe: $(var level)"}""")):
        assert run_file(write(name, text)).user_lines() == [
            'in: inner', 'scoped: outer', 'unscoped: leaked', 'maybe: leaked'], name


def test_environment_tags(write, run_file):
    path = write('e.launch.xml', """
        <launch>
          <set_env name="FE_VAR" value="one"/>
          <append_env name="FE_VAR" value="two" separator=","/>
          <log message="env: $(env FE_VAR none)"/>
          <unset_env name="FE_VAR"/>
          <log message="after: $(env FE_VAR none)"/>
        </launch>""")
    assert run_file(path).user_lines() == ['env: one,two', 'after: none']
    assert isinstance(parse_xml_action('<set_env name="a" value="b"/>'), SetEnvironmentVariable)
    assert isinstance(parse_xml_action('<append_env name="a" value="b" prepend="true"/>'),
                      AppendEnvironmentVariable)


def test_timer_runs_its_children_later(write, run_file):
    path = write('t.launch.yaml', """
        launch:
        - timer:
            period: 0.1
            children:
            - log: {message: fired}
        - log: {message: first}""")
    assert run_file(path).user_lines() == ['first', 'fired']


def test_timer_period_may_be_a_substitution(write, run_file):
    path = write('t.launch.xml', """
        <launch>
          <arg name="p" default="0.05"/>
          <timer period="$(var p)"><log message="fired"/></timer>
        </launch>""")
    assert run_file(path).user_lines() == ['fired']


def test_executable_splits_its_command_line():
    action = parse_xml_action(
        '<executable cmd="echo one \'two three\' $(env HOME)" cwd="/" name="e" '
        'shell="false" output="screen" args="--x y"><env name="A" value="b"/></executable>')
    assert isinstance(action, ExecuteProcess)
    assert [texts(token) for token in action.cmd[:3]] == [['echo'], ['one'], ['two three']]
    assert type(action.cmd[3][0]).__name__ == 'EnvironmentVariable'
    assert [texts(token) for token in action.cmd[4:]] == [['--x'], ['y']]


def test_other_tags(write):
    assert isinstance(parse_xml_action('<unset name="x"/>'), UnsetLaunchConfiguration)
    assert isinstance(parse_xml_action('<shutdown reason="done"/>'), Shutdown)
    group = parse_xml_action('<group forwarding="false"><log message="m"/></group>')
    assert isinstance(group, GroupAction) and len(group.actions) == 1


def test_xml_includes_xml_with_arguments_that_stay_set(write, run_file):
    write('sub/child.launch.xml', """
        <launch>
          <arg name="who" default="nobody"/>
          <log message="child for $(var who) in $(dirname)"/>
        </launch>""")
    path = write('parent.launch.xml', """
        <launch>
          <include file="$(dirname)/sub/child.launch.xml"><arg name="who" value="kid"/></include>
          <log message="after: $(var who) $(dirname)"/>
        </launch>""")
    sub = path.parent / 'sub'
    assert run_file(path).user_lines() == [f'child for kid in {sub}', f'after: kid {sub}']


def test_yaml_includes_python_and_python_includes_xml_and_yaml(write, run_file):
    write('xml_child.launch.xml', '<launch><log message="xml child $(var n)"/></launch>')
    write('yaml_child.launch.yaml', 'launch:\n- log: {message: "yaml child $(var n)"}\n')
    write('py_child.launch.py', """
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription, LogInfo
        from launch.launch_description_sources import AnyLaunchDescriptionSource
        from launch.substitutions import LaunchConfiguration, ThisLaunchFileDir
        from launch_xml.launch_description_sources import XMLLaunchDescriptionSource


        def generate_launch_description():
            return LaunchDescription([
                LogInfo(msg=['python child ', LaunchConfiguration('n')]),
                IncludeLaunchDescription(XMLLaunchDescriptionSource(
                    [ThisLaunchFileDir(), '/xml_child.launch.xml']),
                    launch_arguments=[('n', '2')]),
                IncludeLaunchDescription(AnyLaunchDescriptionSource(
                    [ThisLaunchFileDir(), '/yaml_child.launch.yaml']),
                    launch_arguments=[('n', '3')]),
            ])
        """)
    path = write('top.launch.yaml', """
        launch:
        - include:
            file: $(dirname)/py_child.launch.py
            arg: [{name: n, value: "1"}]""")
    assert run_file(path).user_lines() == ['python child 1', 'xml child 2', 'yaml child 3']


def test_explicit_front_end_sources(write, run_file, tmp_path):
    xml_path = write('x.launch.xml', '<launch><log message="x"/></launch>')
    yaml_path = write('y.launch.yaml', 'launch:\n- log: {message: y}\n')
    assert XMLLaunchDescriptionSource(str(xml_path)).method == 'interpreted XML launch file'
    assert YAMLLaunchDescriptionSource(str(yaml_path)).method == 'interpreted YAML launch file'
    source = FrontendLaunchDescriptionSource(str(xml_path))
    assert source.method == 'interpreted frontend launch file'
    python = write('p.launch.py', f"""
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import FrontendLaunchDescriptionSource
        from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource


        def generate_launch_description():
            return LaunchDescription([
                IncludeLaunchDescription(FrontendLaunchDescriptionSource({str(xml_path)!r})),
                IncludeLaunchDescription(YAMLLaunchDescriptionSource({str(yaml_path)!r})),
            ])
        """)
    assert run_file(python).user_lines() == ['x', 'y']
