"""Spec files: a good one loads; bad ones fail with file, line and what is wrong."""
from __future__ import annotations

import pytest
from speccheck import SpecError, load_spec

GOOD = """\
description: sensor and filter
nodes:
  /sensor_publisher:
    package: my_robot_pkg
    executable: sensor_publisher
    parameters:
      publish_rate: {type: double, value: 2.0}
  /data_processor:
topics:
  /distance:
    type: std_msgs/msg/Float32
    publishers: [/sensor_publisher]
    subscribers: [/data_processor]
    rate: {min: 1.5, max: 2.5}
arguments:
  sim_mode: {default: true, choices: [true, false]}
  robot_ns: {required: true}
"""


def test_a_good_spec_loads_into_typed_requirements(write_spec):
    spec = load_spec(write_spec(GOOD))
    assert [node.name for node in spec.nodes] == ['/sensor_publisher', '/data_processor']
    sensor = spec.node('/sensor_publisher')
    assert (sensor.package, sensor.executable) == ('my_robot_pkg', 'sensor_publisher')
    rate = sensor.parameters[0]
    assert (rate.name, rate.type, rate.value, rate.has_value) == ('publish_rate', 'double', 2.0,
                                                                  True)
    assert spec.node('/data_processor').parameters is None
    topic = spec.topics[0]
    assert (topic.publishers, topic.subscribers, topic.rate_min, topic.rate_max) == (
        ('/sensor_publisher',), ('/data_processor',), 1.5, 2.5)
    sim_mode, robot_ns = spec.arguments
    assert (sim_mode.default, sim_mode.choices) == ('true', ('true', 'false'))
    assert robot_ns.required and robot_ns.default is None


@pytest.mark.parametrize(('text', 'line', 'message'), [
    # a misspelt key is an error, not a requirement silently dropped
    ('topics:\n  /distance:\n    type: std_msgs/msg/Float32\n    publisher: [/a]\n', 4,
     "topics./distance.publisher: unknown key 'publisher' (allowed here: publishers, rate, "
     'subscribers, type)'),
    ('node:\n  /a: {}\n', 1, "node: unknown key 'node'"),
    ('nodes:\n  /a:\n    parameters:\n      rate: {type: float}\n', 4,
     "nodes./a.parameters.rate.type: 'float' is not one of"),
    ('nodes:\n  /ok: {}\n  sensor_publisher: {}\n', 3,
     "nodes.sensor_publisher: 'sensor_publisher' is not a valid name here"),
    ('topics:\n  /t:\n    rate: {min: fast}\n', 3, "topics./t.rate.min: 'fast' is not of type"),
    ('nodes:\n  /a:\n    parameters:\n      r: {type: double, value: 1.0, min: 0}\n', 4,
     "give either 'value' or 'min', not both"),
    ('arguments:\n  robot:\n    default: x\n    required: true\n', 2,
     "give either 'default' or 'required', not both"),
    ('- just\n- a list\n', 1, "top level: ['just', 'a list'] is not of type 'object'"),
])
def test_schema_errors_name_file_line_and_problem(write_spec, text, line, message):
    path = write_spec(text)
    with pytest.raises(SpecError) as caught:
        load_spec(path)
    assert str(caught.value).startswith(f'{path}:{line}: ')
    assert message in str(caught.value)


def test_every_schema_error_is_listed(write_spec):
    path = write_spec('nodes:\n  /a: {pkg: x}\ntopics:\n  /t: {type: 3}\n')
    with pytest.raises(SpecError) as caught:
        load_spec(path)
    lines = str(caught.value).splitlines()
    assert [line.split(': ')[0] for line in lines] == [f'{path}:2', f'{path}:4']


def test_yaml_syntax_error_names_file_and_line(write_spec):
    path = write_spec('nodes:\n  /a:\n    package: [my_robot_pkg\n  /b: {}\n')
    with pytest.raises(SpecError, match=rf'^{path}:4: YAML syntax error: '):
        load_spec(path)


def test_duplicate_key_is_an_error(write_spec):
    path = write_spec('nodes:\n  /a: {}\n  /a: {package: x}\n')
    with pytest.raises(SpecError, match=rf"^{path}:3: duplicate key '/a' \(first at line 2\)"):
        load_spec(path)


def test_missing_file_is_named(tmp_path):
    with pytest.raises(SpecError, match='nope.yaml: no such spec file'):
        load_spec(tmp_path / 'nope.yaml')


def test_an_empty_spec_asks_for_nothing(write_spec):
    spec = load_spec(write_spec(''))
    assert (spec.nodes, spec.topics, spec.arguments) == ((), (), ())
