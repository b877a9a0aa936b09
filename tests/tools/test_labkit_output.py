"""labkit's Background.output: the stretch of a log a lesson shows, independent of
how long the command ran before the cell printed it."""
from __future__ import annotations

import sys

import labkit
import pytest

LINES = ['starting', 'Reading #1', 'Reading #2', 'Reading #3', 'user interrupted',
         'process has finished cleanly', 'done']
PRINTER = 'import sys\nfor line in sys.argv[1:]:\n    print(line, flush=True)'


@pytest.fixture(scope='module')
def printed() -> labkit.Background:
    command = labkit.start([sys.executable, '-c', PRINTER, *LINES])
    command.wait(timeout=30)
    return command


def test_everything_by_default_and_the_last_lines(printed):
    assert printed.output().splitlines() == LINES
    assert printed.output(last=2).splitlines() == LINES[-2:]


def test_until_ends_at_the_first_matching_line(printed):
    assert printed.output(until=r'Reading #\d').splitlines() == LINES[:2]
    assert printed.output(until=r'Reading #3').splitlines() == LINES[:4]


def test_since_starts_at_the_first_matching_line(printed):
    assert printed.output(since='user interrupted').splitlines() == LINES[4:]
    assert printed.output(since='Reading', until='#2').splitlines() == LINES[1:3]
    assert printed.output(since='Reading', last=2).splitlines() == LINES[-2:]


def test_a_pattern_never_printed(printed):
    assert printed.output(since='never printed') == ''
    assert printed.output(until='never printed').splitlines() == LINES
