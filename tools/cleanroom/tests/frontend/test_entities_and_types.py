"""XML and YAML entities: attribute reading, type coercion, nested entities, errors."""
from __future__ import annotations

import io
import xml.etree.ElementTree as ET

import pytest
import yaml
from launch.frontend import Entity
from launch.frontend.type_utils import get_typed_value, infer_value
from launch_xml import Entity as XMLEntity
from launch_yaml import Entity as YAMLEntity


def xml(text: str) -> XMLEntity:
    return XMLEntity(ET.parse(io.StringIO(text)).getroot())


def yaml_entity(text: str) -> YAMLEntity:
    (type_name, body), = yaml.safe_load(text).items()
    return YAMLEntity(body, type_name)


@pytest.mark.parametrize(('text', 'expected'), [
    ('7', 7), ('2.5', 2.5), ('true', True), ('True', True), ('yes', True), ("'42'", '42'),
    ('hello', 'hello'), ('[1, 2, 3]', [1, 2, 3]), ('[a, b]', ['a', 'b']),
    ('$(var x)', '$(var x)'), ('{a: 1}', '{a: 1}'), ('[unclosed', '[unclosed'),
])
def test_inferred_types_follow_yaml(text, expected):
    assert infer_value(text) == expected
    assert type(infer_value(text)) is type(expected)


@pytest.mark.parametrize(('value', 'data_type', 'expected'), [
    ('12', str, '12'), ('12', int, 12), ('0.5', float, 0.5), ('TRUE', bool, True),
    ('false', bool, False), (['1', '2'], list[int], [1, 2]), ('x', list[str], ['x']),
])
def test_explicit_types(value, data_type, expected):
    assert get_typed_value(value, data_type) == expected


def test_a_value_that_does_not_fit_stays_text_unless_forbidden():
    assert get_typed_value('maybe', bool) == 'maybe'
    with pytest.raises(ValueError, match="could not convert string to float: 'soon'"):
        get_typed_value('soon', float, can_be_str=False)
    with pytest.raises(ValueError, match='bool'):
        get_typed_value('maybe', bool, can_be_str=False)


def test_xml_attributes_are_coerced_on_read():
    entity = xml('<param name="p" value="7" other="1.5" flag="true"/>')
    assert entity.type_name == 'param' and entity.parent is None
    assert entity.get_attr('name') == 'p'
    assert entity.get_attr('value', data_type=None) == 7
    assert entity.get_attr('other', data_type=float) == 1.5
    assert entity.get_attr('flag', data_type=bool) is True
    assert entity.get_attr('absent', optional=True) is None


def test_xml_value_separator_makes_a_list():
    entity = xml('<param name="l" value="x;2;z" value-sep=";"/>')
    assert entity.get_attr('value', data_type=None) == ['x', 2, 'z']
    entity.get_attr('name')
    entity.assert_entity_completely_parsed()  # value-sep counts as read


def test_xml_missing_attribute_error_is_jazzys():
    with pytest.raises(AttributeError) as error:
        xml('<node pkg="p"/>').get_attr('exec')
    assert str(error.value) == "Attribute 'exec' of type '<class 'str'>' not found in Entity 'node'"


def test_xml_unread_attributes_are_reported():
    entity = xml('<node pkg="p" exec="e" colour="red"/>')
    entity.get_attr('pkg')
    entity.get_attr('exec')
    with pytest.raises(ValueError) as error:
        entity.assert_entity_completely_parsed()
    assert str(error.value) == "Unexpected attribute(s) found in `node`: {'colour'}"


def test_xml_children_and_nested_entities():
    entity = xml('<node><param name="a"/><remap from="x" to="y"/><param name="b"/></node>')
    assert [child.type_name for child in entity.children] == ['param', 'remap', 'param']
    params = entity.get_attr('param', data_type=list[Entity])
    assert [p.get_attr('name') for p in params] == ['a', 'b']
    assert params[0].parent is entity
    assert entity.get_attr('env', data_type=list[Entity], optional=True) is None
    with pytest.raises(AttributeError, match="Attribute 'env'"):
        entity.get_attr('env', data_type=list[Entity])


def test_yaml_values_keep_their_yaml_type():
    entity = yaml_entity('param: {name: p, value: "42", number: 7, flag: "true", l: [1, 2]}')
    assert entity.get_attr('value', data_type=None) == '42'
    assert entity.get_attr('number', data_type=None) == 7
    assert entity.get_attr('flag', data_type=None) == 'true'
    assert entity.get_attr('l', data_type=None) == [1, 2]
    assert entity.get_attr('name') == 'p'


def test_yaml_numbers_read_as_text_when_text_is_asked_for():
    entity = yaml_entity('arg: {name: speed, default: 1.5}')
    assert entity.get_attr('default') == '1.5'


def test_yaml_children_and_nested_lists():
    entity = yaml_entity("""
group:
  scoped: false
  children:
  - log: {message: a}
  - node: {pkg: p, exec: e, param: [{name: x, value: 1}]}
""")
    children = entity.children
    assert [c.type_name for c in children] == ['log', 'node']
    params = children[1].get_attr('param', data_type=list[Entity])
    assert [p.type_name for p in params] == ['param']
    assert params[0].get_attr('value', data_type=None) == 1
    assert entity.get_attr('scoped', data_type=bool) is False
    entity.assert_entity_completely_parsed()


def test_yaml_missing_and_unread_attributes():
    entity = yaml_entity('node: {pkg: p, colour: red}')
    with pytest.raises(AttributeError) as error:
        entity.get_attr('exec')
    assert str(error.value) == "Attribute 'exec' of type '<class 'str'>' not found in Entity 'node'"
    entity.get_attr('pkg')
    with pytest.raises(ValueError) as unread:
        entity.assert_entity_completely_parsed()
    assert str(unread.value) == "Unexpected attribute(s) found in `node`: {'colour'}"


def test_yaml_entity_must_be_a_mapping():
    with pytest.raises(TypeError, match="Entity 'log' expected a mapping"):
        YAMLEntity(['x'], 'log')
