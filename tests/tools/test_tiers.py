"""Every test gets one tier marker, from its folder or from the fixtures it uses."""
from __future__ import annotations

import tomllib

from textbook import paths
from textbook.pytest_plugin import TIERS, tier_of


def test_a_folder_gives_its_tier():
    assert tier_of(paths.ROOT / 'tests/site/test_browser.py', set()) == 'site'
    assert tier_of(paths.ROOT / 'tests/lessons/test_lessons.py', set()) == 'lesson'
    assert tier_of(paths.ROOT / 'tests/exercises/test_ch06_exercises.py', set()) == 'exercise'
    assert tier_of(paths.ROOT / 'tools/cleanroom/tests/launch/test_x.py', set()) == 'ros'


def test_elsewhere_a_ros_fixture_makes_a_ros_test_and_the_rest_are_unit_tests():
    here = paths.ROOT / 'tests/tools/test_labkit_launch.py'
    assert tier_of(here, {'ros_env', 'tmp_path'}) == 'ros'
    assert tier_of(here, {'tmp_path'}) == 'unit'


def test_the_tiers_are_the_registered_markers_and_no_other_marker_passes():
    options = tomllib.loads((paths.ROOT / 'pyproject.toml').read_text())['tool']['pytest']
    registered = {line.split(':')[0] for line in options['ini_options']['markers']}
    assert set(TIERS) <= registered
    assert '--strict-markers' in options['ini_options']['addopts']


def test_this_test_is_in_the_unit_tier(request):
    assert request.node.get_closest_marker('unit') is not None
    assert request.node.get_closest_marker('ros') is None
