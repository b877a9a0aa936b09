"""tools/bench/ci_time.py: test times summed by folder, slowest first."""
from __future__ import annotations

import importlib.util

from textbook import paths

_spec = importlib.util.spec_from_file_location('ci_time', paths.ROOT / 'tools/bench/ci_time.py')
ci_time = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ci_time)

TIMES = {'tests/lessons/test_lessons.py::test_lesson_executes[a.md]': 100.0,
         'tests/lessons/test_lessons.py::test_lesson_executes[b.md]': 50.0,
         'tools/cleanroom/tests/cli/test_launch.py::test_x': 30.0,
         'tests/test_top.py::test_y': 1.0}


def test_tests_are_summed_by_folder_slowest_first():
    assert ci_time.by_folder(TIMES) == [('tests/lessons', 150.0, 2),
                                        ('tools/cleanroom/tests/cli', 30.0, 1),
                                        ('tests', 1.0, 1)]


def test_the_report_names_totals_and_the_slowest_tests():
    text = ci_time.report(TIMES, top=1)
    assert text.splitlines()[0] == '     181 s in 4 tests (about 2 min on 2 workers)'
    assert text.splitlines()[-1] == \
        '     100 s  tests/lessons/test_lessons.py::test_lesson_executes[a.md]'
