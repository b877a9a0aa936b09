"""launch_ros tags: node (params, remaps, args), push_ros_namespace, set_parameter, set_remap."""
from __future__ import annotations

import io
import xml.etree.ElementTree as ET

import pytest
import yaml
from launch import LaunchContext
from launch.frontend import Parser
from launch.substitutions import LaunchConfiguration, TextSubstitution
from launch.utilities import perform_substitutions
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap
from launch_ros.frontend import parse_node
from launch_ros.parameter_descriptions import ParameterFile, ParameterValue
from launch_ros.substitutions import ExecutableInPackage
from launch_xml import Entity as XMLEntity
from launch_yaml import Entity as YAMLEntity


def xml(text: str) -> XMLEntity:
    return XMLEntity(ET.parse(io.StringIO(text)).getroot())


def yaml_entity(text: str) -> YAMLEntity:
    (type_name, body), = yaml.safe_load(text).items()
    return YAMLEntity(body, type_name)


def text_of(substitutions) -> str:
    return perform_substitutions(LaunchContext(), substitutions)


@pytest.fixture
def parser() -> Parser:
    return Parser()


def test_node_attributes(parser):
    cls, kwargs = parse_node(xml(
        '<node pkg="p" exec="talker" name="n" namespace="ns" exec_name="proc" output="screen" '
        'args="a \'b c\'" ros_args="--log-level warn" if="true"/>'), parser)
    assert cls is Node
    assert {key: text_of(kwargs[key]) for key in ('package', 'executable', 'name', 'namespace',
                                                   'exec_name', 'output')} == {
        'package': 'p', 'executable': 'talker', 'name': 'n', 'namespace': 'ns',
        'exec_name': 'proc', 'output': 'screen'}
    assert [text_of(a) for a in kwargs['arguments']] == ['a', 'b c']
    assert [text_of(a) for a in kwargs['ros_arguments']] == ['--log-level', 'warn']
    assert 'condition' in kwargs


def test_node_is_built(parser):
    node = parser.parse_action(xml('<node pkg="p" exec="talker"/>'))
    assert isinstance(node, Node)
    assert isinstance(node.cmd[0][0], ExecutableInPackage)


def test_empty_namespace_is_the_root(parser):
    _, kwargs = parse_node(xml('<node pkg="p" exec="t" namespace=""/>'), parser)
    assert text_of(kwargs['namespace']) == '/'


def test_xml_params_are_typed_like_jazzy(parser):
    _, kwargs = parse_node(xml("""
        <node pkg="p" exec="t">
          <param name="a_str" value="hello"/>
          <param name="quoted" value="'42'"/>
          <param name="an_int" value="7"/>
          <param name="yes" value="yes"/>
          <param name="ints" value="[1, 2]"/>
          <param name="forced" value="12" type="str"/>
          <param name="sep" value="x;y" value-sep=";"/>
          <param name="subst" value="$(var speed)"/>
          <param name="group"><param name="inner" value="0.1"/></param>
          <param from="/some/file.yaml"/>
        </node>"""), parser)
    params = kwargs['parameters']
    assert params[:5] == [{'a_str': 'hello'}, {'quoted': '42'}, {'an_int': 7}, {'yes': True},
                          {'ints': [1, 2]}]
    forced = params[5]['forced']
    assert isinstance(forced, ParameterValue) and forced.value_type is str
    assert params[6] == {'sep': ['x', 'y']}
    assert isinstance(params[7]['subst'][0], LaunchConfiguration)
    assert params[8] == {'group': {'inner': 0.1}}
    assert text_of(params[9]) == '/some/file.yaml'


def test_yaml_params_keep_yaml_types(parser):
    _, kwargs = parse_node(yaml_entity("""
node:
  pkg: p
  exec: t
  param:
  - {name: text_number, value: "42"}
  - {name: text_bool, value: "true"}
  - {name: floats, value: [1.5, 2.0]}
  - {name: group, param: [{name: inner, value: 1}]}
  - {from: /f.yaml}
  remap:
  - {from: a, to: b}
"""), parser)
    params = kwargs['parameters']
    assert params[:4] == [{'text_number': '42'}, {'text_bool': 'true'}, {'floats': [1.5, 2.0]},
                          {'group': {'inner': 1}}]
    assert text_of(params[4]) == '/f.yaml'
    assert [(text_of(s), text_of(d)) for s, d in kwargs['remappings']] == [('a', 'b')]


def test_unknown_param_type(parser):
    with pytest.raises(ValueError, match="Unknown parameter type 'complex'"):
        parse_node(xml('<node pkg="p" exec="t"><param name="x" value="1" type="complex"/></node>'),
                   parser)


def test_unread_param_attribute_is_reported(parser):
    with pytest.raises(ValueError, match=r'Unexpected attribute\(s\) found in `param`'):
        parse_node(xml('<node pkg="p" exec="t"><param name="x" value="1" vlaue="2"/></node>'),
                   parser)


def test_scope_tags(parser):
    for tag in ('push_ros_namespace', 'push-ros-namespace'):
        action = parser.parse_action(xml(f'<{tag} namespace="robot1"/>'))
        assert isinstance(action, PushRosNamespace) and text_of(action.namespace) == 'robot1'
    remap = parser.parse_action(xml('<set_remap from="chatter" to="news"/>'))
    assert isinstance(remap, SetRemap)
    assert (text_of(remap.src), text_of(remap.dst)) == ('chatter', 'news')
    param = parser.parse_action(yaml_entity('set_parameter: {name: flag, value: "true"}'))
    assert isinstance(param, SetParameter)
    assert [type(s) for s in param.value] == [TextSubstitution]


def test_find_pkg_share_in_a_launch_file(write, run_file, tmp_path, monkeypatch):
    prefix = tmp_path / 'install' / 'fe_share_pkg'
    marker = prefix / 'share/ament_index/resource_index/packages/fe_share_pkg'
    marker.parent.mkdir(parents=True)
    marker.write_text('')
    monkeypatch.setenv('AMENT_PREFIX_PATH', str(prefix))
    path = write('s.launch.xml', """
        <launch>
          <log message="share: $(find-pkg-share fe_share_pkg)"/>
          <log message="prefix: $(find-pkg-prefix fe_share_pkg)"/>
        </launch>""")
    assert run_file(path).user_lines() == [f'share: {prefix}/share/fe_share_pkg',
                                           f'prefix: {prefix}']


def test_param_file_with_substitutions_allowed(parser):
    _, kwargs = parse_node(xml(
        '<node pkg="p" exec="t"><param from="/f.yaml" allow_substs="true"/></node>'), parser)
    param_file = kwargs['parameters'][0]
    assert isinstance(param_file, ParameterFile) and param_file.allow_substs is True
