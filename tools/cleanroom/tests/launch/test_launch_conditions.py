"""Conditions and their error messages (golden 21)."""
from __future__ import annotations

import pytest
from launch import LaunchContext
from launch.conditions import (
    IfCondition,
    InvalidConditionExpressionError,
    LaunchConfigurationEquals,
    LaunchConfigurationNotEquals,
    UnlessCondition,
    evaluate_condition_expression,
)
from launch.substitutions import LaunchConfiguration
from launch.utilities import normalize_to_list_of_substitutions


@pytest.fixture
def context() -> LaunchContext:
    ctx = LaunchContext()
    ctx.launch_configurations.update({'flag': 'True', 'mode': 'sim'})
    return ctx


@pytest.mark.parametrize('text,expected', [('true', True), ('True', True), (' 1 ', True),
                                           ('false', False), ('FALSE', False), ('0', False)])
def test_valid_expressions(context, text, expected):
    assert evaluate_condition_expression(
        context, normalize_to_list_of_substitutions(text)) is expected
    assert IfCondition(text).evaluate(context) is expected
    assert UnlessCondition(text).evaluate(context) is not expected


def test_invalid_expression_message(context):
    context.launch_configurations['flag'] = 'maybe'
    config = LaunchConfiguration('flag')
    with pytest.raises(InvalidConditionExpressionError) as info:
        IfCondition(config).evaluate(context)
    assert str(info.value) == (
        "invalid condition expression, expected one of [true, 1, false, 0] but got 'maybe', "
        f"expanded from '{config!r}'")


def test_launch_configuration_equals_is_deprecated_with_a_python_warning(context):
    with pytest.warns(UserWarning, match='deprecated'):
        equals = LaunchConfigurationEquals('mode', 'sim')
    with pytest.warns(UserWarning):
        not_equals = LaunchConfigurationNotEquals('mode', 'sim')
    assert equals.evaluate(context) is True
    assert not_equals.evaluate(context) is False
    with pytest.warns(UserWarning):
        unset = LaunchConfigurationEquals('unset', None)
    assert unset.evaluate(context) is True
