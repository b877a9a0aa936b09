"""Check 7.4's expected values come from the capstone's config, at check time."""
from __future__ import annotations

from labkit.checks import ch07_04


def test_the_nodes_read_are_the_nodes_given_values():
    for robot in ch07_04.ROBOTS:
        for shift in ('day', 'night'):
            assert {v.node for v in ch07_04.expected(robot, shift)} == set(ch07_04.VALUE_NODES)


def test_values_follow_the_capstone_layers_and_the_brief():
    turtle2_day = {v.name: v.value for v in ch07_04.expected('turtle2', 'day')}
    turtle2_night = {v.name: v.value for v in ch07_04.expected('turtle2', 'night')}
    assert turtle2_day['max_linear'] == ch07_04.capstone_value('turtle2', 'controller',
                                                              'max_linear')
    assert turtle2_night['max_linear'] == turtle2_day['max_linear'] / 2
    inspector = {v.name: v.value for v in ch07_04.expected('turtle3', 'day')}
    assert inspector == ch07_04.INSPECTOR_VALUES
