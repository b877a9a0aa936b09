"""Fixtures of the launch_ros tests: a colcon-built package.

The private ROS domain, the token marking every process the tests start
(the session fails if one survives) and `run_launch` are ../conftest.py's,
shared with launch/.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).parent


@pytest.fixture(scope='session', autouse=True)
def _in_launch_test_session(launch_test_session: str) -> None:
    """Every test here runs in the marked session of ../conftest.py (one check for all)."""


@pytest.fixture(scope='session')
def built_package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Build fixture_pkg/lr_test_pkg with colcon once; return its install prefix."""
    ws = tmp_path_factory.mktemp('ws')
    shutil.copytree(HERE / 'fixture_pkg', ws / 'src')
    colcon = shutil.which('colcon', path=os.path.dirname(sys.executable)) or 'colcon'
    subprocess.run([colcon, 'build'], cwd=ws, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.STDOUT, timeout=120)
    return ws / 'install' / 'lr_test_pkg'


@pytest.fixture
def test_package(built_package: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The built package, made findable as `source install/setup.bash` would.

    Its prefix goes on AMENT_PREFIX_PATH (ament index) and its site-packages
    on PYTHONPATH (console scripts).
    """
    site = next(built_package.glob('lib/python3*/site-packages'))
    for var, value in (('AMENT_PREFIX_PATH', built_package), ('PYTHONPATH', site)):
        old = os.environ.get(var)
        monkeypatch.setenv(var, str(value) + (os.pathsep + old if old else ''))
    return built_package
