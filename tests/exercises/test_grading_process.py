"""The exercise tests' grading process: a verdict comes back whole, and a child
that hangs is killed and graded once more, never waited for without end."""
from __future__ import annotations

from pathlib import Path

import pytest

from . import _grading_process as grading_process

#: A stand-in child: hangs (sleeps) on the attempts listed in a file, else answers.
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


def test_a_child_that_hangs_is_killed_and_the_case_graded_again(tmp_path, capsys):
    with pytest.warns(grading_process.GradingHang, match='grading ex999 .* hung') as hangs:
        verdict = grade(tmp_path, {1})
    assert verdict.results == [(True, 'met'), (False, 'not met')]
    assert (tmp_path / 'tries').read_text() == 'xx'
    log = capsys.readouterr().out
    assert f'grading attempt 1 of ex999 hung for {GUARD:g} s and was killed' in log
    # the hang's evidence: what it printed, where its Python code waited, its threads
    report = Path(str(hangs[0].message).rsplit('stacks: ', 1)[1])
    evidence = report.read_text()
    report.unlink()
    assert 'observing the graph' in evidence
    assert 'time.sleep(600)' in evidence or 'File "<string>", line 9' in evidence, evidence
    assert 'Thread 1' in evidence or 'gdb is not installed' in evidence, evidence


def test_a_case_that_hangs_every_time_fails_naming_it(tmp_path):
    with pytest.warns(grading_process.GradingHang) as hangs, \
            pytest.raises(AssertionError, match=r'grading ex999 hung 2 times \(5 s each\)'):
        grade(tmp_path, {1, 2})
    assert (tmp_path / 'tries').read_text() == 'xx'
    assert len(hangs) == 2
    for hang in hangs:
        Path(str(hang.message).rsplit('stacks: ', 1)[1]).unlink()
