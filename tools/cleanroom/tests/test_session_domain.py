"""The session's ROS domain: exported, held against every other process, and in
the book's `make test` (which runs these tests with tests/ in one session) the
domain the book's plugin leased, whichever suite's test a worker ran first."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest

#: the book's pytest plugin (tools/textbook), as conftest.py names it
BOOK_PLUGIN = 'textbook.pytest_plugin'


def test_the_session_domain_is_exported_and_held_against_other_processes(
        ros_domain: int, request: pytest.FixtureRequest):
    assert os.environ['ROS_DOMAIN_ID'] == str(ros_domain)
    if request.config.pluginmanager.has_plugin(BOOK_PLUGIN):
        assert ros_domain == request.getfixturevalue('session_lease').domain_id
    attempt = subprocess.run(
        [sys.executable, '-c', 'from rclhelpers.domains import lease_domain; '
         f'lease_domain(timeout=0, ids=range({ros_domain}, {ros_domain + 1}))'],
        capture_output=True, text=True, timeout=60)
    assert attempt.returncode != 0
    assert f'no free ROS domain: IDs {ros_domain}-{ros_domain} are all held' in attempt.stderr
