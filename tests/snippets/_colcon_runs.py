"""A package's own tests run as a student runs them: a scratch workspace holding a
copy of the package, `colcon build`, `colcon test`, `colcon test-result --verbose`.

Every run is marked in its environment, so a test can fail on any process the
run left behind (and stop it).  Shared by the tests of lesson 6.15
(dock_watch_pkg) and of the capstone (capstone_bringup).
"""
from __future__ import annotations

import re
import shutil
import subprocess
import uuid
from collections.abc import Callable, Iterator
from pathlib import Path

import psutil
from labkit.grading.student_package import StudentPackage
from textbook import paths


def left_behind(mark: str, token: str) -> list[psutil.Process]:
    """Live processes whose environment carries `mark`=`token`."""
    found = []
    for proc in psutil.process_iter():
        try:
            if proc.environ().get(mark) == token and proc.status() != psutil.STATUS_ZOMBIE:
                found.append(proc)
        except (psutil.AccessDenied, psutil.NoSuchProcess, psutil.ZombieProcess):
            continue
    return found


def marked_environment(env: dict[str, str], mark: str) -> Iterator[dict[str, str]]:
    """For a fixture: `env` marked for this run; afterwards, fails the test if a marked
    process survived (having stopped it)."""
    token = uuid.uuid4().hex
    yield dict(env, **{mark: token})
    leftovers = left_behind(mark, token)
    for proc in leftovers:
        proc.kill()
    assert not leftovers, f'processes left behind: {leftovers}'


def run(argv: list[str], env: dict[str, str], cwd: Path,
        timeout: float) -> subprocess.CompletedProcess[str]:
    """A command as the student's terminal runs it (`timeout` only stops a hung run)."""
    return subprocess.run(argv, env=env, cwd=cwd, capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, timeout=timeout, check=False)


def build_copy(root: Path, package: str, env: dict[str, str], timeout: float,
               edit: Callable[[Path], None] | None = None) -> dict[str, str]:
    """A workspace in `root` with a copy of snippets' `package` (changed by `edit` if
    given), built; returns the environment of `source install/setup.bash`."""
    copy = root / 'src' / package
    shutil.copytree(paths.SNIPPETS / package, copy,
                    ignore=shutil.ignore_patterns('__pycache__'))
    if edit is not None:
        edit(copy)
    build = run([paths.executable('colcon'), 'build'], env, root, timeout)
    assert build.returncode == 0, build.stdout + build.stderr
    return StudentPackage(root, package).environment(env)


def colcon_test(root: Path, package: str, env: dict[str, str], timeout: float
                ) -> tuple[subprocess.CompletedProcess[str], dict[str, str]]:
    """`colcon test`, then `colcon test-result --verbose`; its result and each test's outcome."""
    tested = run([paths.executable('colcon'), 'test', '--packages-select', package], env, root,
                 timeout)
    assert tested.returncode == 0, tested.stdout + tested.stderr  # failing tests are not errors
    result = run([paths.executable('colcon'), 'test-result', '--verbose'], env, root, timeout)
    report = root / 'build' / package / 'pytest.xml'
    outcomes = {}
    for case in re.finditer(r'<testcase [^>]*name="(\w+)"[^>]*?(/>|>(.*?)</testcase>)',
                            report.read_text(), re.S):
        failed = case.group(3) and re.search(r'<(failure|error)\b', case.group(3))
        outcomes[case.group(1)] = 'failed' if failed else 'passed'
    return result, outcomes
