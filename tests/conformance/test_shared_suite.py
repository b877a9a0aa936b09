"""The shared launch conformance suite (../shared/conformance), when present:
our launch, launch_ros and ros2 must behave as recorded from ROS 2 Jazzy."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest
from textbook import paths

SUITE = paths.ROOT.parent / "shared" / "conformance"

pytestmark = [
    pytest.mark.skipif(not SUITE.is_dir(), reason=f"no conformance suite at {SUITE}"),
    pytest.mark.timeout(1800),
]


def run_check(script: str, tmp_path) -> str:
    result = subprocess.run(
        [sys.executable, str(SUITE / script), "--python", sys.executable,
         "--workdir", str(tmp_path), "-v"],
        cwd=tmp_path, env=dict(os.environ), capture_output=True, text=True, timeout=1700)
    return result.stdout + result.stderr


def test_launch_api_conformance(tmp_path):
    out = run_check("check.py", tmp_path)
    assert "32 passed, 0 failed" in out, out


def test_ros2_cli_conformance(tmp_path):
    out = run_check("cli_check.py", tmp_path)
    assert "11 passed, 0 failed" in out, out
