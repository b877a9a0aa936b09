"""The headless turtlesim's motion model on its own (no ROS, no clock): the
square, the one-second command, integration, clamping, spawn names."""
from __future__ import annotations

import importlib.util
import math
import sys

import pytest
from textbook import paths

_SOURCE = paths.SNIPPETS / 'turtlesim' / 'turtlesim_headless' / 'world.py'
_spec = importlib.util.spec_from_file_location('turtlesim_world_under_test', _SOURCE)
world = importlib.util.module_from_spec(_spec)
sys.modules[_spec.name] = world  # dataclasses look their module up
_spec.loader.exec_module(world)


def test_the_square_and_its_centre_are_turtlesims():
    assert f'{world.WORLD_SIZE:f}' == '11.088889'
    assert f'{world.CENTRE:f}' == '5.544445'


@pytest.mark.parametrize('theta,expected', [
    (0.0, 0.0), (math.pi / 2, math.pi / 2), (3 * math.pi / 2, -math.pi / 2),
    (-3 * math.pi / 2, math.pi / 2), (math.pi, -math.pi), (5 * math.pi, -math.pi)])
def test_headings_are_kept_in_minus_pi_to_pi(theta, expected):
    assert world.normalize_angle(theta) == pytest.approx(expected)


def test_a_command_counts_for_exactly_one_second_of_the_updates():
    turtle = world.Turtle('t', 1.0, 1.0, 0.0)
    turtle.command(2.0, 0.0, 0.0, now=10.0)
    turtle.step(9.5, 10.3)  # only 10.0..10.3 is covered by the command
    assert turtle.x == pytest.approx(1.6)
    turtle.step(10.3, 12.0)  # the command ran out at 11.0
    assert turtle.x == pytest.approx(3.0)
    turtle.step(12.0, 13.0)
    assert turtle.x == pytest.approx(3.0)
    assert turtle.velocities(11.0) == (2.0, 0.0, 0.0)
    assert turtle.velocities(11.01) == (0.0, 0.0, 0.0)


def test_turning_and_moving_follow_the_heading():
    turtle = world.Turtle('t', 5.0, 5.0, 0.0)
    turtle.command(0.0, 0.0, math.pi / 2, now=0.0)
    turtle.step(0.0, 1.0)
    assert (turtle.x, turtle.y, turtle.theta) == pytest.approx((5.0, 5.0, math.pi / 2))
    turtle.command(1.0, 1.0, 0.0, now=1.0)  # sideways only when holonomic
    turtle.step(1.0, 2.0)
    assert (turtle.x, turtle.y) == pytest.approx((5.0, 6.0))
    turtle.command(0.0, 1.0, 0.0, now=2.0)
    turtle.step(2.0, 3.0, holonomic=True)
    assert (turtle.x, turtle.y) == pytest.approx((4.0, 6.0))  # its left is -x now


def test_the_walls_hold_and_report_where_the_turtle_would_have_been():
    turtle = world.Turtle('t', 11.0, 0.5, 0.0)
    turtle.command(1.0, 0.0, 0.0, now=0.0)
    turtle.step(0.0, 0.5)
    assert turtle.clamp() == pytest.approx((11.5, 0.5))
    assert (turtle.x, turtle.y) == (world.WORLD_SIZE, 0.5)
    assert turtle.clamp() is None
    turtle.teleport_absolute(-1.0, 20.0, 0.0)
    assert turtle.clamp() == (-1.0, 20.0)
    assert (turtle.x, turtle.y) == (0.0, world.WORLD_SIZE)


def test_teleport_relative_turns_before_it_moves():
    turtle = world.Turtle('t', 2.0, 2.0, 0.0)
    turtle.teleport_relative(1.0, math.pi / 2)
    assert (turtle.x, turtle.y, turtle.theta) == pytest.approx((2.0, 3.0, math.pi / 2))


def test_spawn_names_count_up_and_a_taken_name_is_refused():
    sim = world.World()
    assert sim.reset().name == 'turtle1'
    assert sim.spawn(1.0, 1.0, 0.0).name == 'turtle2'
    sim.kill('turtle2')
    assert sim.spawn(1.0, 1.0, 0.0, 'turtle3').name == 'turtle3'
    assert sim.spawn(1.0, 1.0, 0.0).name == 'turtle4'
    with pytest.raises(KeyError):
        sim.spawn(1.0, 1.0, 0.0, 'turtle1')
    with pytest.raises(KeyError):
        sim.kill('nobody')
    sim.reset()
    assert list(sim.turtles) == ['turtle1']
    assert (sim.turtles['turtle1'].x, sim.turtles['turtle1'].y) == (world.CENTRE, world.CENTRE)
