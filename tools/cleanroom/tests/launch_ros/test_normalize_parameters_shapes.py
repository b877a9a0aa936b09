"""Shapes and errors of launch_ros.utilities' normalizers, as observed on the Jazzy
reference (launch_ros 0.26): remapping rules, parameters, and what evaluating them gives."""
import re
import sys
import types

import launch_ros.utilities
import pytest
from launch import LaunchContext, Substitution
from launch.substitutions import LaunchConfiguration, TextSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import Parameter, ParameterFile, ParameterValue
from launch_ros.utilities import (
    evaluate_parameters,
    normalize_parameters,
    normalize_remap_rule,
    normalize_remap_rules,
)


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
    return ('TextSubstitution', f"'{value}'")


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


# -- parameters -----------------------------------------------------------------------------

def LC(name):
    return ('LaunchConfiguration', f"LaunchConfig('{name}')")


@pytest.fixture
def context():
    context = LaunchContext()
    context.launch_configurations.update({'cfg': 'cv', 'i': '5', 'l': '[1, 2]', 'd': '{a: 1}'})
    return context


def one(value):
    """The normalized value of {'a': value}."""
    (normalized,) = normalize_parameters([{'a': value}])
    ((name, result),) = normalized.items()
    assert shape(name) == (text('a'),)
    return shape(result)


@pytest.mark.parametrize('value, normalized', [
    (1, 1), (2.5, 2.5), (True, True), (b'by', b'by'),
    ('x', (text('x\n...\n'),)), ('1', (text("'1'\n"),)),
    (LaunchConfiguration('cfg'), (LC('cfg'),)),
    ([1, 2, 3], (1, 2, 3)), ([1, 2.5], (1.0, 2.5)), ([2.5, 1], (2.5, 1.0)), ((1, 2), (1, 2)),
    ([True, False], (True, False)), ([], ()),
    (['x', 'y'], ([text('x\n...\n')], [text('y\n...\n')])),
    ([1, 'x'], ([text('1\n...\n')], [text('x\n...\n')])),
    ([TextSubstitution(text='x'), 'y'], (text('x'), text('y'))),
    ([['x', 'y'], ['z']], ([text('x'), text('y')], [text('z')])),
    ([[TextSubstitution(text='x'), 'y'], 'z'], ([text('x'), text('y')], [text('z\n...\n')])),
    (bytearray(b'a'), (97,)),
])
def test_values_are_normalized_to_jazzys_shapes(value, normalized):
    assert one(value) == normalized


def test_names_are_tuples_of_substitutions_and_nested_dicts_are_flattened():
    (normalized,) = normalize_parameters([{
        'a': {'b': {'c': 1}, 'd': 2}, 'a.b': 3, ('x', LaunchConfiguration('cfg')): 4,
        LaunchConfiguration('cfg'): {'y': 5}, 'empty': {}}])
    dot = text('.')
    assert shape(normalized) == {
        (text('a'), dot, text('b'), dot, text('c')): 1, (text('a'), dot, text('d')): 2,
        (text('a.b'),): 3, (text('x'), LC('cfg')): 4, (LC('cfg'), dot, text('y')): 5}


def test_other_entries_are_parameter_files_and_descriptions_are_kept():
    parameter = Parameter('n', 3)
    described = ParameterFile('/tmp/p.yaml', allow_substs=True)
    normalized = normalize_parameters(['/tmp/p.yaml', ['/tmp/', 'p.yaml'], parameter, described])
    assert isinstance(normalized, tuple)
    assert [shape(entry.param_file) for entry in normalized[:2]] == [
        [text('/tmp/p.yaml')], [text('/tmp/'), text('p.yaml')]]
    assert normalized[2:] == (parameter, described)
    assert shape(parameter.name) == [text('n')]
    assert shape(ParameterValue(LaunchConfiguration('cfg')).value) == [LC('cfg')]


PARAM_FILE_TYPES = ("[<class 'str'>, <class 'launch.substitution.Substitution'>, "
                    "<class 'collections.abc.Iterable'>, <class 'os.PathLike'>, <class 'bytes'>]")


@pytest.mark.parametrize('parameters, message', [
    ({'a': 1}, "Expecting list of parameters, got {'a': 1}"),
    ('/tmp/x.yaml', 'Expecting list of parameters, got /tmp/x.yaml'),
    ([{1: 2}], "'int' object is not iterable"),
    ([{'a': None}], 'Unexpected type for parameter value None'),
    ([{'a': {1}}], 'Unexpected type for parameter value {1}'),
    ([{'a': [{'b': 1}]}], "Failed to handle type {'b': 1}"),
    ([{'a': [None]}], "Expected 'subvalue' to be one of [<class 'float'>, <class 'int'>, "
                      "<class 'str'>, <class 'bool'>, <class 'str'>, "
                      "<class 'launch.substitution.Substitution'>, "
                      "<class 'collections.abc.Iterable'>], but got 'None' of type "
                      "'<class 'NoneType'>'"),
    ([5], f"'ParameterFile()' expected 'param_file' to be one of {PARAM_FILE_TYPES}, but got "
          "'5' of type '<class 'int'>'"),
])
def test_normalize_errors_are_jazzys(parameters, message):
    with pytest.raises((TypeError, RuntimeError), match=f'^{re.escape(message)}$'):
        normalize_parameters(parameters)


@pytest.mark.parametrize('value, evaluated', [
    ('x', 'x'), ('1', '1'), ('', ''), (b'by', b'by'), ([1, 2.5], (1.0, 2.5)),
    (['x', 'y'], ('x', 'y')), ([1, True], (1, True)),
    (LaunchConfiguration('i'), 5), (LaunchConfiguration('l'), (1, 2)),
    ([LaunchConfiguration('i'), '0'], 50), ([LaunchConfiguration('cfg'), '_s'], 'cv_s'),
    ([[LaunchConfiguration('i')], [LaunchConfiguration('i'), '0']], (5, 50)),
    ([['x', 'y'], ['z']], ('xy', 'z')),
    (ParameterValue([1, 2]), [1, 2]), (ParameterValue(['a', 'b']), ['a', 'b']),
    (ParameterValue(TextSubstitution(text='5'), value_type=int), 5),
])
def test_values_evaluate_as_on_jazzy(context, value, evaluated):
    (result,) = evaluate_parameters(context, normalize_parameters([{'a': value}]))
    assert result == {'a': evaluated}
    assert type(result['a']) is type(evaluated)


STR_HINT = ('If the parameter is meant to be a string, try wrapping it in '
            'launch_ros.parameter_descriptions.ParameterValue(value, value_type=str)')
NOT_UNIFORM = ('Expected a non-empty sequence, with items of uniform type. Allowed sequence '
               'item types are bool, int, float, str. Got inconsistent input for "a"')


@pytest.mark.parametrize('value, message', [
    ([1, 'x'], NOT_UNIFORM), ([True, 1], NOT_UNIFORM), ([[], []], NOT_UNIFORM),
    ([[TextSubstitution(text='a')], [TextSubstitution(text='1')]], NOT_UNIFORM),
    (TextSubstitution(text='[1.5, 2]'), NOT_UNIFORM),
    (LaunchConfiguration('d'), "Allowed value types are bytes, bool, int, float, str, "
                               "Sequence[bool], Sequence[int], Sequence[float], Sequence[str]. "
                               f"Got <class 'dict'> for \"a\". {STR_HINT}"),
    (TextSubstitution(text='a: b: c'), f'Unable to parse the value of parameter a as yaml. '
                                       f'{STR_HINT}'),
    ([], "Expected 'value' to be one of [<class 'float'>, <class 'int'>, <class 'str'>, "
         "<class 'bool'>, <class 'bytes'>], but got '()' of type '<class 'tuple'>'"),
])
def test_evaluate_errors_are_jazzys(context, value, message):
    normalized = normalize_parameters([{'a': value}])
    with pytest.raises(TypeError, match=f'^{re.escape(message)}$'):
        evaluate_parameters(context, normalized)


def test_public_names_are_jazzys():
    assert launch_ros.utilities.__all__ == [
        'add_node_name', 'evaluate_parameters', 'evaluate_parameters_dict',
        'get_node_name_count', 'is_namespace_absolute', 'is_root_namespace',
        'make_namespace_absolute', 'normalize_parameters', 'normalize_parameters_dict',
        'normalize_remap_rule', 'normalize_remap_rules', 'prefix_namespace',
        'to_parameters_list']
    for absent in ('normalize_parameter_dict', 'evaluate_parameter_dict',
                   'evaluate_parameters_dict', 'normalize_parameters_dict'):
        assert not hasattr(launch_ros.utilities, absent)
    assert not hasattr(sys.modules['launch_ros.utilities.normalize_remap_rule'],
                       'evaluate_remap_rules')
    assert launch_ros.utilities.is_root_namespace('/')
    assert launch_ros.utilities.make_namespace_absolute(None) is None
