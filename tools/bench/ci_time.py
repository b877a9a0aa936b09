"""Where `make test` spends its time: build/test-times.json summed by folder.

    .venv/bin/python tools/bench/ci_time.py [build/test-times.json] [--top 15]

Every test session writes build/test-times.json (textbook.pytest_plugin:
setup + call + teardown per test).  This prints the worker-seconds of each
folder (tests/lessons, tests/exercises, tools/cleanroom/tests/cli, ...), their
share of the whole, and the slowest tests, so speed work starts where the
time is.  Wall time is about the sum divided by the workers (2 in CI).
"""
from __future__ import annotations

import argparse
import json
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
#: Folders summed as one line; anything else is summed by its first two parts.
DEPTH = {'tools/cleanroom/tests': 4, 'tests': 2}


def folder_of(nodeid: str) -> str:
    """'tests/lessons/test_lessons.py::test_x[a]' -> 'tests/lessons'."""
    parts = nodeid.split('::')[0].split('/')
    for prefix, depth in DEPTH.items():
        if '/'.join(parts[:len(prefix.split('/'))]) == prefix:
            return '/'.join(parts[:min(depth, len(parts) - 1)])
    return '/'.join(parts[:2])


def by_folder(times: dict[str, float]) -> list[tuple[str, float, int]]:
    """(folder, seconds, tests), slowest folder first."""
    seconds: dict[str, float] = defaultdict(float)
    counts: dict[str, int] = defaultdict(int)
    for nodeid, duration in times.items():
        seconds[folder_of(nodeid)] += duration
        counts[folder_of(nodeid)] += 1
    return sorted(((f, seconds[f], counts[f]) for f in seconds), key=lambda row: -row[1])


def report(times: dict[str, float], top: int = 15) -> str:
    total = sum(times.values()) or 1.0
    lines = [f'{total:8.0f} s in {len(times)} tests (about {total / 2 / 60:.0f} min on 2 workers)',
             '', 'by folder:']
    lines += [f'{seconds:8.0f} s {100 * seconds / total:5.1f} % {count:5d}  {folder}'
              for folder, seconds, count in by_folder(times)]
    lines += ['', f'slowest {top}:']
    lines += [f'{duration:8.0f} s  {nodeid}'
              for nodeid, duration in sorted(times.items(), key=lambda row: -row[1])[:top]]
    return '\n'.join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('times', nargs='?', type=Path, default=ROOT / 'build/test-times.json')
    parser.add_argument('--top', type=int, default=15)
    options = parser.parse_args(argv)
    print(report(json.loads(options.times.read_text()), options.top))
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
