"""Benchmark `make test`'s worker count: the same tests on W workers, for several W.

    .venv/bin/python tools/bench/bench_test_workers.py [--workers 2 3 4] [--rounds 1] \
        [-- <pytest selection, default: a mix of lesson-like, CLI and exercise tests>]

Much of a ROS test's time is spent waiting (discovery settling, a launch
coming up, a topic's rate measured over a window), not computing, so more
workers than cores can finish sooner; too many make tests compete for the
CPU.  For each worker count the script runs the selection through
`python -m textbook test -n W` (the command `make test` runs) and reports its
wall time and the ratio to the first count, the reference measured in the
same run.  Rounds alternate the order of the counts, so a machine that
slows down during the benchmark does not favour one of them.  Every run
must pass: a count that makes tests fail is reported as failing, not fast.
"""
from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_SELECTION = ['tools/cleanroom/tests/cli', 'tests/snippets/test_ch06_lessons_63_64.py',
                     'tests/exercises', '-k', 'cli or lesson or ex63 or ex64']


def run_once(workers: int, selection: list[str]) -> tuple[float, int, str]:
    """Wall seconds, exit code and pytest's summary (its FAILED/ERROR lines and its
    last line) for one run on `workers` workers."""
    start = time.monotonic()
    result = subprocess.run([sys.executable, '-m', 'textbook', 'test', '-n', str(workers),
                             '-q', '-p', 'no:cacheprovider', *selection],
                            cwd=ROOT, capture_output=True, text=True)
    lines = [line for line in result.stdout.splitlines() if line.strip()]
    failures = [line for line in lines if line.startswith(('FAILED ', 'ERROR '))]
    return (time.monotonic() - start, result.returncode,
            '\n'.join([*failures, lines[-1] if lines else '']))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--workers', type=int, nargs='+', default=[2, 3, 4],
                        help='worker counts; the first is the reference (default 2 3 4)')
    parser.add_argument('--rounds', type=int, default=1, help='runs of each count (default 1)')
    parser.add_argument('selection', nargs='*', help='pytest arguments (after --)')
    options = parser.parse_args(argv)
    selection = options.selection or DEFAULT_SELECTION
    times: dict[int, list[float]] = {count: [] for count in options.workers}
    failed = False
    for round_number in range(options.rounds):
        order = options.workers if round_number % 2 == 0 else options.workers[::-1]
        for count in order:
            seconds, code, summary = run_once(count, selection)
            times[count].append(seconds)
            failed |= code != 0
            print(f'round {round_number + 1}, {count} workers: {seconds:7.1f} s  exit {code}  '
                  f'{summary}', flush=True)
    reference = statistics.median(times[options.workers[0]])
    print(f"\n{'workers':>8} {'median s':>9} {'ratio':>6}")
    for count in options.workers:
        median = statistics.median(times[count])
        print(f'{count:>8} {median:>9.1f} {median / reference:>6.2f}')
    if failed:
        print('some runs failed: their times say nothing about speed', file=sys.stderr)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
