"""The shared launch_testing / launch_pytest suite (../shared/conformance/testing),
when present: `launch_test` and pytest with launch_pytest must report what ROS 2
Jazzy reported (exit codes and the summary lines a user reads)."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest
from textbook import paths

SUITE = paths.ROOT.parent / 'shared' / 'conformance' / 'testing'
CASES = sorted(p.name for p in SUITE.glob('test_*.py')) if SUITE.is_dir() else []

pytestmark = [
    pytest.mark.skipif(not SUITE.is_dir(), reason=f'no testing conformance suite at {SUITE}'),
    pytest.mark.timeout(1800),
]


def test_testing_conformance(tmp_path):
    result = subprocess.run(
        [sys.executable, str(SUITE / 'check_testing.py'), '--python', sys.executable,
         '--workdir', str(tmp_path), '-v'],
        cwd=tmp_path, env=dict(os.environ), capture_output=True, text=True, timeout=1700)
    out = result.stdout + result.stderr
    assert f'{len(CASES)} passed, 0 failed' in out, out
    assert result.returncode == 0, out


def test_suite_has_cases():
    """The suite must not silently shrink to nothing."""
    assert len(CASES) >= 7, CASES
