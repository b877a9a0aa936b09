"""Build a test stand-in for an interface package once, and the environment to use it.

The PyPI wheels have no composition_interfaces (`ros2 component
list|load|unload` and the fake container need it) and no package with an
action (`ros2 action` needs one; turtlesim's RotateAbsolute, as on a real
ROS 2).  Each stand-in (./<package>_stand_in, fields as Jazzy's) is built
with colcon, as a student builds an interface package, into build/cache
keyed by its content and the interpreter, so only the first run on a machine
pays for it (~30 s).  A file lock makes parallel test runs wait for one
build.  On a real ROS 2, where the package is installed, nothing is built.
"""
from __future__ import annotations

import fcntl
import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

CACHE = Path(__file__).resolve().parents[4] / 'build' / 'cache' / 'interface_stand_ins'
#: Built as ROS 2's packages are (NDEBUG): a bad field then raises TypeError when a
#: request is sent, instead of failing a C assertion.
CMAKE_ARGS = ['-DCMAKE_BUILD_TYPE=Release']


def _importable(package: str, env: dict[str, str]) -> bool:
    """Whether a process with `env` (not this one: the test run may have put another
    workspace on its own path) imports `package`."""
    return subprocess.run([sys.executable, '-c', f'import {package}'], env=env,
                          capture_output=True, check=False).returncode == 0


def _source(package: str) -> Path:
    return Path(__file__).with_name(f'{package}_stand_in')


def _content_hash(source: Path) -> str:
    digest = hashlib.sha256(' '.join([sys.prefix, *CMAKE_ARGS]).encode())
    for path in sorted(source.rglob('*')):
        if path.is_file():
            digest.update(str(path.relative_to(source)).encode() + path.read_bytes())
    return digest.hexdigest()[:16]


def _build(source: Path, workspace: Path) -> None:
    shutil.rmtree(workspace, ignore_errors=True)
    workspace.mkdir(parents=True)
    env = dict(os.environ, PATH=f'{Path(sys.executable).parent}{os.pathsep}{os.environ["PATH"]}')
    result = subprocess.run(
        [str(Path(sys.executable).with_name('colcon')), '--log-base', str(workspace / 'log'),
         'build', '--base-paths', str(source), '--build-base', str(workspace / 'build'),
         '--install-base', str(workspace / 'install'), '--cmake-args', *CMAKE_ARGS],
        cwd=workspace, env=env, capture_output=True, text=True, timeout=600)
    if result.returncode != 0:
        raise RuntimeError(f'colcon build of the stand-in {source.name} failed:\n'
                           f'{result.stdout[-3000:]}{result.stderr[-3000:]}')
    (workspace / 'done').touch()


def environment(base: dict[str, str], package: str = 'composition_interfaces'
                ) -> dict[str, str]:
    """`base` plus what a sourced install of `package` sets."""
    if _importable(package, base):
        return dict(base)
    CACHE.mkdir(parents=True, exist_ok=True)
    source = _source(package)
    workspace = CACHE / f'{package}-{_content_hash(source)}'
    with open(CACHE / 'build.lock', 'w') as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not (workspace / 'done').exists():
            _build(source, workspace)
    prefix = workspace / 'install' / package
    site = prefix / 'lib' / f'python{sys.version_info.major}.{sys.version_info.minor}' / \
        'site-packages'

    def prepend(name: str, value: Path) -> str:
        return os.pathsep.join(filter(None, [str(value), base.get(name, '')]))
    return {**base, 'PYTHONPATH': prepend('PYTHONPATH', site),
            'LD_LIBRARY_PATH': prepend('LD_LIBRARY_PATH', prefix / 'lib'),
            'AMENT_PREFIX_PATH': prepend('AMENT_PREFIX_PATH', prefix)}
