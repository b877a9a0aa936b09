"""Shapes and errors of launch_ros.utilities' normalizers, as observed on the Jazzy
reference (launch_ros 0.26): remapping rules, parameters, and what evaluating them gives."""
import re
import types

import pytest
from launch import LaunchContext, Substitution
from launch.substitutions import LaunchConfiguration, TextSubstitution
from launch_ros.actions import Node
from launch_ros.utilities import normalize_remap_rule, normalize_remap_rules


def shape(value):
    """Substitutions as (class name, text), containers kept as they are."""
    if isinstance(value, Substitution):
        return (type(value).__name__, value.describe())
    if isinstance(value, tuple):
        return tuple(shape(item) for item in value)
    if isinstance(value, list):
        return [shape(item) for item in value]
    if isinstance(value, dict):
        return {shape(key): shape(item) for key, item in value.items()}
    return value


def text(value):
    return ('TextSubstitution', repr(value))


# -- remapping rules ------------------------------------------------------------------------

def test_remap_rules_are_a_generator_of_tuples_of_substitution_tuples():
    rules = normalize_remap_rules([('a', 'b'), (LaunchConfiguration('c'),
                                               ['x', TextSubstitution(text='y')])])
    assert isinstance(rules, types.GeneratorType)
    assert shape(list(rules)) == [
        ((text('a'),), (text('b'),)),
        ((('LaunchConfiguration', "LaunchConfig('c')"),), (text('x'), text('y'))),
    ]
    assert shape(normalize_remap_rule(('a', 'b'))) == ((text('a'),), (text('b'),))
    normalize_remap_rules(5)  # nothing is checked before the generator is iterated


@pytest.mark.parametrize('rules, message', [
    ([['a', 'b']], "Expected 'remap_rule' to be one of [<class 'tuple'>], but got "
                   "'['a', 'b']' of type '<class 'list'>'"),
    ({'a': 'b'}, "Expected 'remap_rule' to be one of [<class 'tuple'>], but got 'a' of type "
                 "'<class 'str'>'"),
    ('ab', "Expected 'remap_rule' to be one of [<class 'tuple'>], but got 'a' of type "
           "'<class 'str'>'"),
    ([('a', 'b', 'c')], 'remap_rule must be a tuple of length 2, got length 3'),
    ([(1, 2)], "'int' object is not iterable"),
])
def test_remap_rule_errors_are_jazzys_and_node_raises_them_when_made(rules, message):
    with pytest.raises(TypeError, match=f'^{re.escape(message)}$'):
        list(normalize_remap_rules(rules))
    with pytest.raises(TypeError, match=f'^{re.escape(message)}$'):
        Node(executable='x', remappings=rules)


def test_node_remappings_are_substituted_when_executed():
    context = LaunchContext()
    context.launch_configurations['c'] = 'from_topic'
    node = Node(executable='x', remappings=[(LaunchConfiguration('c'), ['to_', 'topic'])])
    node._ros_command_tail(context)
    assert node.expanded_remapping_rules == [('from_topic', 'to_topic')]
