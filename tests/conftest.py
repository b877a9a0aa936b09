"""Shared fixtures.  ROS isolation and the leftover-process check come from
textbook.pytest_plugin, registered here when pytest was started without it."""
from __future__ import annotations

import pytest
from textbook import environment, workspace


def pytest_configure(config: pytest.Config) -> None:
    if not config.pluginmanager.has_plugin('textbook.pytest_plugin'):
        config.pluginmanager.import_plugin('textbook.pytest_plugin')


@pytest.fixture(scope='session')
def ws_install():
    """The snippets workspace, built (or found current) once per test process."""
    return workspace.ensure_built()


@pytest.fixture(scope='session')
def ros_env(session_lease, ws_install) -> dict[str, str]:
    """Environment of a student's terminal: workspace sourced, private domain."""
    return environment.ros_env(session_lease)
