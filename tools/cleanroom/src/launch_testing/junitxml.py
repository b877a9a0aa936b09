"""JUnit XML of launch test results (what `--junit-xml` writes, colcon test-result reads)."""
from __future__ import annotations

import unittest
import xml.etree.ElementTree as ET


def unittestResultsToXml(*, name: str = 'launch_test',  # noqa: N802 - Jazzy's name
                         test_results: dict[str, unittest.TestResult]) -> ET.ElementTree:
    """One <testsuite> per test run, one <testcase> per test method."""
    root = ET.Element('testsuites', name=name)
    totals = {'tests': 0, 'failures': 0, 'errors': 0, 'skipped': 0, 'time': 0.0}
    for run_name, result in test_results.items():
        suite = _suite(run_name, result)
        root.append(suite)
        for key in ('tests', 'failures', 'errors', 'skipped'):
            totals[key] += int(suite.get(key))
        totals['time'] += float(suite.get('time'))
    for key, value in totals.items():
        root.set(key, f'{value:.3f}' if key == 'time' else str(value))
    return ET.ElementTree(root)


def _suite(run_name: str, result: unittest.TestResult) -> ET.Element:
    times = getattr(result, 'testCaseTimes', {})
    suite = ET.Element('testsuite', name=run_name)
    problems = {}
    for kind, entries in (('failure', result.failures), ('error', result.errors)):
        for test, trace in entries:
            problems[test] = (kind, trace)
    skipped = {test: reason for test, reason in result.skipped}
    tests = list(times) or [t for t, _ in result.failures + result.errors]
    if not tests and not result.wasSuccessful():
        # the run itself failed before any test could run
        problems[None] = ('failure', 'The test run did not complete')
        tests = [None]
    for test in tests:
        case = ET.SubElement(
            suite, 'testcase',
            classname=run_name if test is None else _class_name(test),
            name=run_name if test is None else test._testMethodName,
            time=f'{times.get(test, 0.0):.3f}')
        if test in problems:
            kind, trace = problems[test]
            element = ET.SubElement(case, kind, message=trace.strip().splitlines()[-1])
            element.text = trace
        elif test in skipped:
            ET.SubElement(case, 'skipped', message=skipped[test])
    suite.set('tests', str(len(tests)))
    suite.set('failures', str(sum(1 for k, _ in problems.values() if k == 'failure')))
    suite.set('errors', str(sum(1 for k, _ in problems.values() if k == 'error')))
    suite.set('skipped', str(sum(1 for t in tests if t in skipped)))
    suite.set('time', f'{sum(times.values()):.3f}')
    return suite


def _class_name(test: unittest.TestCase) -> str:
    cls = type(test)
    return f'{cls.__module__}.{cls.__qualname__}'
