"""Lesson 6.15: the launch file still meets its spec, read statically.

The cheapest test of the package: no process starts.  The running check is
in test_dock_watch_pytest.py, where launch_pytest starts the system.
"""
from pathlib import Path

import speccheck
from ament_index_python.packages import get_package_share_directory

SHARE = Path(get_package_share_directory('dock_watch_pkg'))


def test_launch_file_meets_spec_statically():
    spec = speccheck.load_spec(SHARE / 'specs' / 'dock_watch_v2.spec.yaml')
    speccheck.check_static(spec, SHARE / 'launch' / 'dock_watch_v2.launch.py', {}).assert_ok()
