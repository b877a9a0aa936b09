"""pytest plugin of launch_testing: collect launch test files (pytest11 entry point).

A file is a launch test when it defines a top-level `generate_test_description`
that is not a launch_pytest fixture; pytest then runs it as `launch_test` would
(one item per file) and reports its unittest output when it fails.  Every other
file is left to pytest's own collection.
"""
from __future__ import annotations

import ast
import os
import signal
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from rclhelpers.processes import stop_group

RUN_TIMEOUT = 900.0
STOP_GRACE = 10.0


def is_launch_test_file(path: Path) -> bool:
    """True when the file defines generate_test_description for launch_testing."""
    if path.suffix != '.py':
        return False
    try:
        tree = ast.parse(path.read_text(encoding='utf-8'), filename=str(path))
    except (OSError, SyntaxError, UnicodeDecodeError):
        return False  # pytest's own collection reports the problem
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and node.name == 'generate_test_description':
            decorators = ' '.join(ast.unparse(d) for d in node.decorator_list)
            return 'launch_pytest' not in decorators
    return False


@pytest.hookimpl(tryfirst=True)
def pytest_pycollect_makemodule(module_path: Path, parent):
    if is_launch_test_file(Path(module_path)):
        return LaunchTestModule.from_parent(parent, path=Path(module_path))
    return None


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line('markers', 'launch_test: a launch_testing test description')


class LaunchTestFailure(Exception):
    """A launch test file whose tests failed; the message is what launch_test printed."""


class LaunchTestModule(pytest.File):
    """A launch test file: one item that runs it with launch_test."""

    def collect(self):
        yield LaunchTestItem.from_parent(self, name=self.path.stem)


class LaunchTestItem(pytest.Item):
    """Runs `launch_test FILE` in its own process group and reads its JUnit report."""

    def runtest(self) -> None:
        with tempfile.TemporaryDirectory(prefix='launch_test-') as folder:
            report = os.path.join(folder, 'report.xml')
            command = [sys.executable, '-m', 'launch_testing.launch_test', str(self.path),
                       '--junit-xml', report]
            returncode, output = _run_in_own_group(command, cwd=str(self.path.parent))
            failures = _failed_tests(report)
        if returncode != 0:
            summary = '\n'.join(failures) if failures else f'launch_test exited {returncode}'
            raise LaunchTestFailure(f'{summary}\n\n{output}')

    def repr_failure(self, excinfo, style=None):
        if isinstance(excinfo.value, LaunchTestFailure):
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self):
        return self.path, None, f'launch_test {self.path.name}'


def _run_in_own_group(command: list[str], cwd: str) -> tuple:
    """Run the command in a new session; kill the whole group if it is interrupted."""
    process = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               start_new_session=True)
    try:
        output, _ = process.communicate(timeout=RUN_TIMEOUT)
    except BaseException:
        _stop_group(process)
        raise
    _stop_group(process)  # nothing of the run may outlive it
    return process.returncode, output


def _stop_group(process: subprocess.Popen) -> None:
    """SIGINT the run's process group, SIGKILL what is left, and reap the run."""
    stop_group(process.pid, ((signal.SIGINT, STOP_GRACE), (signal.SIGKILL, STOP_GRACE)))
    process.wait()


def _failed_tests(report: str) -> list[str] | None:
    """'FAIL: name' / 'ERROR: name' lines from the JUnit report, if one was written."""
    if not os.path.exists(report):
        return None
    lines = []
    for case in ET.parse(report).getroot().iter('testcase'):
        for kind, label in (('failure', 'FAIL'), ('error', 'ERROR')):
            problem = case.find(kind)
            if problem is not None:
                lines.append(f"{label}: {case.get('classname')}.{case.get('name')}: "
                             f"{problem.get('message')}")
    return lines
