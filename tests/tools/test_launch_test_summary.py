"""What a grader says about a `launch_test` run that failed: the test that decided it."""
from __future__ import annotations

import subprocess

import pytest
from labkit.grading.test_run import summary

pytestmark = pytest.mark.unit

# launch_test's report on stderr: active tests, their failures, then the
# post-shutdown tests (whose outcome can depend on the moment of the shutdown).
REPORT = """\
test_safety_monitor_dies (test_fault.TestCapstoneFault.test_safety_monitor_dies) ... ERROR

======================================================================
ERROR: test_safety_monitor_dies (test_fault.TestCapstoneFault.test_safety_monitor_dies)
----------------------------------------------------------------------
Traceback (most recent call last):
RuntimeError: ('Did not receive messages on these topics: ', {'/turtle1/wall_reading'})

----------------------------------------------------------------------
Ran 1 test in 30.012s

FAILED (errors=1)
test_stopped_cleanly (test_fault.TestReaction.test_stopped_cleanly) ... FAIL
test_why (test_fault.TestReaction.test_why) ... ok

======================================================================
FAIL: test_stopped_cleanly (test_fault.TestReaction.test_stopped_cleanly)
AssertionError: 1 not found in [0] : Proc wall_sensor-1 exited with code 1
"""


def _run(stderr: str) -> subprocess.CompletedProcess:
    return subprocess.CompletedProcess(['launch_test', 'test_fault.py'], 1, '', stderr)


def test_names_the_first_test_that_failed_with_its_reason():
    assert summary(_run(REPORT)) == (
        "test_safety_monitor_dies ERROR (RuntimeError: ('Did not receive messages on these "
        "topics: ', {'/turtle1/wall_reading'}))")


def test_a_run_without_failed_tests_shows_how_it_ended():
    ended = _run('Ran 0 tests in 0.000s\n\nOK\n')
    assert summary(ended) == 'no test failed; the run ended with: Ran 0 tests in 0.000s | OK'
