"""Fixtures of the speccheck tests: the snippets workspace sourced in this process,
and spec files written on the fly."""
from __future__ import annotations

import os
from pathlib import Path

import pytest
from ament_index_python.packages import get_package_share_directory

HERE = Path(__file__).parent
LAUNCH_FILES = HERE / 'launch_files'


@pytest.fixture
def sourced(ros_env, monkeypatch):
    """The workspace's ament index visible to this process (static checks run in it)."""
    for name in ('AMENT_PREFIX_PATH', 'PYTHONPATH', 'PATH'):
        if name in ros_env:
            monkeypatch.setenv(name, ros_env[name])
    return ros_env


@pytest.fixture
def installed(sourced):
    """Path of an installed my_robot_pkg launch file, by name."""
    share = Path(get_package_share_directory('my_robot_pkg'))
    return lambda name: share / 'launch' / name


@pytest.fixture
def write_spec(tmp_path):
    """Write YAML text to a spec file and return its path."""
    def write(text: str, name: str = 'spec.yaml') -> Path:
        path = tmp_path / name
        path.write_text(text, encoding='utf-8')
        return path
    return write


def environment_for_subprocess(ros_env: dict[str, str]) -> dict[str, str]:
    env = dict(ros_env)
    env['PYTHONPATH'] = os.pathsep.join(filter(None, [str(HERE.parents[1] / 'tools'),
                                                     env.get('PYTHONPATH')]))
    return env
