"""The clean room's own tests are collected only where the clean room is the
`launch` in use: over a sourced ROS 2 (another `launch` first on the path)
they are not tests of anything installed."""
from __future__ import annotations

import os
import subprocess
import sys

from textbook import paths

CLEANROOM_TESTS = paths.TOOLS / 'cleanroom' / 'tests'


def collected(env: dict[str, str]) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, '-m', 'pytest', '--collect-only', '-q', '-p', 'no:cacheprovider',
         '-p', 'no:launch_testing', '-p', 'no:launch_pytest', str(CLEANROOM_TESTS)],
        cwd=paths.ROOT, env=env, capture_output=True, text=True, timeout=120)


def test_collected_with_the_clean_room():
    result = collected(dict(os.environ))
    assert result.returncode == 0, result.stdout + result.stderr
    assert ' tests collected' in result.stdout


def test_not_collected_over_another_launch(tmp_path):
    (tmp_path / 'launch').mkdir()
    (tmp_path / 'launch' / '__init__.py').write_text('"""A real ROS 2 launch, say."""\n')
    result = collected(dict(os.environ, PYTHONPATH=str(tmp_path)))
    assert 'no tests collected' in result.stdout, result.stdout + result.stderr
