"""Parameter typing: YAML 1.1 for substitution text, Python types kept (goldens 02, 07, 13, 28)."""

import pytest
from launch import LaunchContext
from launch.substitutions import TextSubstitution
from launch_ros.parameter_descriptions import Parameter, ParameterFile, ParameterValue
from launch_ros.utilities import evaluate_parameters, normalize_parameters
from launch_ros.utilities.parameter_values import (
    coerce_text,
    coerce_value,
    flatten_parameters,
    format_parameter_argument,
    plain_python_value,
    yaml_typed,
)


@pytest.mark.parametrize('text, expected', [
    ('007', 7), ('042', 34), ('true', True), ('false', False), ('True', True),
    ('3', 3), ('2.0', 2.0), ('1.5', 1.5), ('my_robot', 'my_robot'), ('yes', True),
    ('[1, 2, 3]', [1, 2, 3]), ('[1, 2.5]', [1.0, 2.5]), ("['a', 'b']", ['a', 'b']),
])
def test_yaml_typed(text, expected):
    value = yaml_typed(text)
    assert value == expected
    assert type(value) is type(expected)


@pytest.mark.parametrize('text', ['{a: 1}', '[1, [2]]', '[1, a]', '', 'key: [', '[]'])
def test_yaml_typed_keeps_text_ros_cannot_store(text):
    assert yaml_typed(text) == text


def test_coerce_text_with_value_type():
    assert coerce_text('007', str) == '007'
    assert coerce_text('1', float) == 1.0 and isinstance(coerce_text('1', float), float)
    assert coerce_text('2.5', float) == 2.5
    assert coerce_text('true', bool) is True
    assert coerce_text('[1, 2]', list[float]) == [1.0, 2.0]
    assert coerce_text('5', int) == 5


def test_coerce_text_rejects_wrong_type():
    with pytest.raises(TypeError, match=r"value='2.5' is not an instance of <class 'int'>"):
        coerce_text('2.5', int)
    with pytest.raises(TypeError, match='is not an instance of'):
        coerce_text('abc', float)


def test_coerce_value_golden_28_text():
    with pytest.raises(TypeError) as info:
        coerce_value('0.5', float)
    assert str(info.value) == "value='0.5' is not an instance of <class 'float'>"


def test_coerce_value_accepts_int_for_float_but_not_bool_for_int():
    assert coerce_value(3, float) == 3.0 and isinstance(coerce_value(3, float), float)
    with pytest.raises(TypeError):
        coerce_value(True, int)
    assert coerce_value([1, 2], list[int]) == [1, 2]
    with pytest.raises(TypeError):
        coerce_value(['a'], list[int])


def test_plain_python_value_keeps_types():
    assert plain_python_value('yes') == 'yes'
    assert plain_python_value(('a', 'b')) == ['a', 'b']
    with pytest.raises(TypeError):
        plain_python_value(object())


def test_flatten_parameters_dotted_names():
    nested = {'limits': {'linear': 0.5, 'angular': {'max': 1.0}}, 'rate': 3}
    assert flatten_parameters(nested) == {
        'limits.linear': 0.5, 'limits.angular.max': 1.0, 'rate': 3}


def test_format_parameter_argument_uses_python_rendering():
    assert format_parameter_argument('use_sim_time', True) == 'use_sim_time:=True'
    assert format_parameter_argument('level', 3) == 'level:=3'


def test_normalized_and_evaluated_parameters_have_jazzys_shapes():
    """Observed on Jazzy (launch_ros 0.26): tuples all the way, a plain list becomes a
    tuple, a typed one stays the list YAML makes, a Parameter is handed on as itself,
    an empty list is refused (its items have no type), and object's own reprs."""
    context = LaunchContext()
    normalized = normalize_parameters([{'a': ['lidar'], 'd': {'e': [1.0]}, 'f': 3}])
    assert isinstance(normalized, tuple)
    assert evaluate_parameters(context, normalized) == ({'a': ('lidar',), 'd.e': (1.0,), 'f': 3},)
    typed = ParameterValue(TextSubstitution(text='[1, 2]'), value_type=list[int])
    assert evaluate_parameters(context, normalize_parameters([{'v': typed}])) == ({'v': [1, 2]},)
    parameter = Parameter('z', 5)
    assert evaluate_parameters(context, normalize_parameters([parameter])) == (parameter,)
    with pytest.raises(TypeError, match=r"^Expected 'value' to be one of \[<class 'float'>, "
                       r".*but got '\(\)' of type '<class 'tuple'>'$"):
        evaluate_parameters(context, normalize_parameters([{'h': []}]))
    for described in (typed, parameter, ParameterFile('/tmp/x.yaml')):
        assert repr(described).startswith(f'<launch_ros.parameter_descriptions.'
                                           f'{type(described).__name__} object at 0x')


WRONG_KIND = (r'^value should be either a scalar, a substitutions, or a mixed list of scalars '
              r'and substitutions\. Got `value=.*` of type `<class .*>`\. $')
WRONG_ITEM = (r'^value is a list, and one of the items is not a scalar, a Substitution or a '
              r"list of substitutions\. Got value='.*'$")


@pytest.mark.parametrize('value, error', [
    (None, WRONG_KIND), (object(), WRONG_KIND), (ParameterValue(1), WRONG_KIND),
    ([[1]], WRONG_ITEM), ([['a']], WRONG_ITEM), (['a', ['b']], WRONG_ITEM),
    ([ParameterValue(1)], WRONG_ITEM),
    ([1, 'x'], r"^Input value is not an acceptable 'SomeValueType'\.Got value='\[1, 'x'\]'$"),
    ([1, True], r"^Input value is not an acceptable 'SomeValueType'\.Got value='\[1, True\]'$"),
    ((x for x in [1]), r"^object of type 'generator' has no len\(\)$"),
])
def test_values_jazzy_refuses_when_described(value, error):
    """Observed on Jazzy: ParameterValue and Parameter refuse these at once (TypeError),
    a Parameter given a ParameterValue included."""
    with pytest.raises(TypeError, match=error):
        ParameterValue(value)
    if not isinstance(value, type(x for x in [])):
        with pytest.raises(TypeError, match=error):
            Parameter('a', value)


@pytest.mark.parametrize('value, evaluated, shown', [
    ((1, 2), [1, 2], '[1, 2]'), ({1}, [1], '[1]'), ({'a': 1}, ['a'], "['a']"),
    (b'x', [120], '[120]'), ([1.0, 2], [1.0, 2.0], '[1.0, 2.0]'), ([], [], '[]'),
    ([True, False], [True, False], '[True, False]'), ('x', 'x', 'x'),
])
def test_values_jazzy_takes_and_how_it_shows_them(value, evaluated, shown):
    described = ParameterValue(value)
    assert described.evaluate(LaunchContext()) == evaluated
    assert str(described) == f'launch_ros.description.ParameterValue(value={shown}, ' \
        'value_type=None)'


def test_a_list_of_substitutions_of_different_types_is_not_uniform():
    with pytest.raises(ValueError, match=r'^The output list is not uniform$'):
        ParameterValue([1, TextSubstitution(text='x')]).evaluate(LaunchContext())
    assert str(Parameter('a', 1)).startswith(
        'launch_ros.description.Parameter(name=[<launch.substitutions.text_substitution.'
        'TextSubstitution object at 0x')
