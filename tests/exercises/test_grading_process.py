"""The exercise tests' grading process: a verdict comes back whole, and a child
that hangs is killed and its case fails naming the evidence, never waited for
without end and never graded again."""
from __future__ import annotations

from pathlib import Path

import pytest

from . import _grading_process as grading_process

#: A stand-in child: hangs (sleeps) on the attempts listed, else answers (counted in a file).
CHILD = """
import json, sys, time
from pathlib import Path
exercise, workspace, package = sys.argv[1:]
tries = Path(workspace) / 'tries'
tries.write_text(tries.read_text() + 'x' if tries.exists() else 'x')
if len(tries.read_text()) in {hang_on}:
    print('observing the graph', flush=True)
    time.sleep(600)
print('a line a check printed')
print(json.dumps({{'title': 'Exercise 9.9.9', 'results': [[True, 'met'], [False, 'not met']]}}))
"""
#: Seconds; the stand-in answers at once or sleeps 600 s, so this is no speed limit.
GUARD = 5.0


def grade(tmp_path: Path, hang_on: set[int]):
    return grading_process.grade('ex999', tmp_path, 'ex_pkg', GUARD,
                                 CHILD.format(hang_on=sorted(hang_on)))


def test_the_verdict_comes_back_from_the_child(tmp_path):
    verdict = grade(tmp_path, set())
    assert verdict.title == 'Exercise 9.9.9'
    assert verdict.results == [(True, 'met'), (False, 'not met')]
    assert not verdict.passed and verdict.problems == ['not met']
    assert (tmp_path / 'tries').read_text() == 'x'


def test_a_child_that_hangs_is_killed_and_the_case_fails_naming_its_stacks(tmp_path):
    with pytest.raises(AssertionError, match=rf'grading ex999 \(ex_pkg\) hung for {GUARD:g} s '
                       'and was killed; its stacks are in ') as failure:
        grade(tmp_path, {1})
    assert (tmp_path / 'tries').read_text() == 'x', 'a hung case must not be graded again'
    # the hang's evidence: what it printed, where its Python code waited, its threads
    report = Path(str(failure.value).rsplit('its stacks are in ', 1)[1])
    evidence = report.read_text()
    report.unlink()
    assert 'observing the graph' in evidence
    assert 'time.sleep(600)' in evidence or 'File "<string>", line 9' in evidence, evidence
    assert 'Thread 1' in evidence or 'gdb is not installed' in evidence, evidence
