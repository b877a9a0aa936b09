"""Fixtures of the launch_testing / launch_pytest tests.

Each test runs its launch tests in subprocesses marked by a token in their
environment (children inherit it); a test fails if one of them survives it.
"""
from __future__ import annotations

import os
import subprocess
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest
from _leftovers import marked_processes

CASES = Path(__file__).parent / 'cases'
TOKEN_VAR = 'CLEANROOM_TESTING_TEST_TOKEN'


@pytest.fixture
def run_env(ros_domain: int, tmp_path: Path) -> Iterator[dict[str, str]]:
    """Environment for a launch test subprocess; no process of it may outlive the test."""
    token = uuid.uuid4().hex
    env = dict(os.environ, ROS_LOG_DIR=str(tmp_path / 'log'), PYTHONDONTWRITEBYTECODE='1',
               RCUTILS_COLORIZED_OUTPUT='0', PYTHONWARNINGS='ignore')
    env[TOKEN_VAR] = token
    yield env
    leftovers = marked_processes(token, TOKEN_VAR)
    for proc in leftovers:
        proc.kill()
    assert not leftovers, f'processes left behind: {leftovers}'


@pytest.fixture
def run(run_env: dict[str, str]):
    """Run a command in cases/; return the CompletedProcess."""
    def runner(*argv: str, timeout: float = 240) -> subprocess.CompletedProcess:
        return subprocess.run(list(argv), cwd=CASES, env=run_env, stdin=subprocess.DEVNULL,
                              capture_output=True, text=True, timeout=timeout)
    return runner
