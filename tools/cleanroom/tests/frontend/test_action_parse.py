"""`Action.parse` and `Action.get_sub_entities`, as in Jazzy: what every frontend tag
gives its action is `(Action, kwargs)` with the condition of `if` / `unless`."""
from __future__ import annotations

import io

import pytest
from launch import Action, LaunchContext
from launch.conditions import IfCondition, UnlessCondition
from launch.frontend import Parser


def tag(xml: str):
    root, parser = Parser.load(io.StringIO(f'<launch>{xml}</launch>'))
    return root.children[0], parser


def test_if_and_unless_become_the_condition():
    kind, kwargs = Action.parse(*tag('<foo if="$(env NO_SUCH_VARIABLE 1)"/>'))
    assert kind is Action and isinstance(kwargs['condition'], IfCondition)
    assert kwargs['condition'].evaluate(LaunchContext())
    kind, kwargs = Action.parse(*tag('<foo unless="true"/>'))
    assert isinstance(kwargs['condition'], UnlessCondition)
    assert not kwargs['condition'].evaluate(LaunchContext())
    assert Action.parse(*tag('<foo/>')) == (Action, {})


def test_a_subclass_parses_to_action_too():
    class Mine(Action):
        pass
    assert Mine.parse(*tag('<foo if="1"/>'))[0] is Action


def test_if_with_unless_is_refused():
    with pytest.raises(RuntimeError, match='^if and unless conditions can.t be used'):
        Action.parse(*tag('<foo if="1" unless="0"/>'))


def test_an_action_holds_no_entities():
    assert Action().get_sub_entities() == []
