"""The snippets workspace: ``snippets/`` built with colcon into ``build/ws``.

Built normally (not ``--symlink-install``): like a student's workspace, the
installed copy only changes when colcon runs, which lesson 6.4 relies on.
Rebuilt from clean only when the content of ``snippets/`` (or the Python
environment) changed; a file lock makes parallel runs wait for one build.
"""
from __future__ import annotations

import fcntl
import functools
import os
import shutil
import subprocess
import sys
from contextlib import contextmanager
from pathlib import Path

from . import paths
from .fingerprint import hash_paths, hash_text

INSTALL = paths.WORKSPACE / 'install'

# Snippets packages that stand in for a ROS package (``share/<name>/HEADLESS``
# marks our build of one); skipped where the environment has the real one.
STAND_INS = ('turtlesim',)


class WorkspaceBuildError(RuntimeError):
    """colcon failed; the message carries its output."""


def workspace_hash(snippets: Path = paths.SNIPPETS) -> str:
    """Changes whenever a snippet, the pinned packages, the interpreter or the
    set of stand-ins the environment provides for real change."""
    lock = paths.ROOT / 'requirements' / 'lock.txt'
    return hash_text(hash_paths([snippets], base=snippets.parent),
                     lock.read_text() if lock.exists() else '', sys.prefix,
                     ' '.join(skipped_packages()))


def installed_for_real(package: str, env: dict[str, str] | None = None) -> str | None:
    """The prefix on ``AMENT_PREFIX_PATH`` with a real ``package``, if there is one.

    What ``ros2 pkg prefix`` would find, except our own headless builds.
    """
    env = os.environ if env is None else env
    for prefix in filter(None, env.get('AMENT_PREFIX_PATH', '').split(os.pathsep)):
        root = Path(prefix)
        if (root / 'share/ament_index/resource_index/packages' / package).is_file() \
                and not (root / 'share' / package / 'HEADLESS').exists():
            return prefix
    return None


def skipped_packages(env: dict[str, str] | None = None) -> list[str]:
    """Stand-ins not to build: the environment has the real package (never shadow it)."""
    return [name for name in STAND_INS if installed_for_real(name, env)]


@contextmanager
def _build_lock(workspace: Path):
    workspace.parent.mkdir(parents=True, exist_ok=True)
    with open(workspace.parent / f'{workspace.name}.lock', 'w') as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        yield


def colcon_command(snippets: Path = paths.SNIPPETS,
                   workspace: Path = paths.WORKSPACE) -> list[str]:
    """The colcon call: the student's ``colcon build``, pointed at our folders."""
    skip = skipped_packages()
    return [paths.executable('colcon'), '--log-base', str(workspace / 'log'), 'build',
            '--base-paths', str(snippets), '--build-base', str(workspace / 'build'),
            '--install-base', str(workspace / 'install'),
            *(['--packages-skip', *skip] if skip else [])]


def ensure_built(snippets: Path = paths.SNIPPETS, workspace: Path = paths.WORKSPACE) -> Path:
    """Build ``snippets`` unless ``workspace/install`` is current; returns that folder.

    Each content version is built from clean into ``generations/<hash>/``, and
    ``build``, ``install`` and ``log`` are then switched to it atomically
    (symlinks), so nodes and lessons running from the previous install are
    never pulled out from under them, and a failed build leaves it in place.
    """
    install = workspace / 'install'
    with _build_lock(workspace):
        generation = workspace / 'generations' / workspace_hash(snippets)[:16]
        if (install / 'setup.bash').exists() \
                and install.resolve() == (generation / 'install').resolve():
            return install
        previous = install.resolve().parent if install.is_symlink() else None
        shutil.rmtree(generation, ignore_errors=True)
        generation.mkdir(parents=True)
        env = dict(os.environ, PATH=paths.tool_path())
        result = subprocess.run(colcon_command(snippets, generation), cwd=generation, env=env,
                                capture_output=True, text=True, timeout=600)
        if result.returncode != 0:
            raise WorkspaceBuildError(
                f"colcon build of {paths.rel(snippets)} failed (exit {result.returncode}); "
                f"logs in {paths.rel(generation / 'log')}\n{result.stdout[-4000:]}"
                f"{result.stderr[-4000:]}")
        for sub in ('build', 'install', 'log'):
            _switch(workspace / sub, generation / sub)
        _prune(workspace / 'generations', keep={generation, previous})
        return install


def _switch(link: Path, target: Path) -> None:
    """Point ``link`` at ``target`` in one step (replacing an old folder or link)."""
    if link.is_dir() and not link.is_symlink():
        shutil.rmtree(link)
    temporary = link.with_name(f'.{link.name}.{os.getpid()}')
    temporary.unlink(missing_ok=True)
    temporary.symlink_to(os.path.relpath(target, link.parent))
    os.replace(temporary, link)


def _prune(generations: Path, keep: set[Path | None]) -> None:
    """Delete builds older than the current and the previous one."""
    for old in generations.iterdir():
        if old not in keep:
            shutil.rmtree(old, ignore_errors=True)


@functools.lru_cache(maxsize=8)
def _sourced(install: str, base_items: tuple[tuple[str, str], ...]) -> tuple[tuple[str, str], ...]:
    script = f'source "{install}/setup.bash" >/dev/null && env -0'
    out = subprocess.run(['bash', '-c', script], env=dict(base_items), check=True,
                         capture_output=True, timeout=60).stdout
    pairs = (entry.split(b'=', 1) for entry in out.split(b'\0') if b'=' in entry)
    return tuple((k.decode(), v.decode()) for k, v in pairs)


def sourced_env(base: dict[str, str], install: Path = INSTALL) -> dict[str, str]:
    """``base`` after ``source install/setup.bash``, as a student's shell would have it.

    Sourcing is done by bash itself (the real setup script), once per process
    and base environment.
    """
    env = dict(_sourced(str(install), tuple(sorted(base.items()))))
    for noise in ('_', 'SHLVL', 'PWD', 'OLDPWD'):
        env.pop(noise, None)
        if noise in base:
            env[noise] = base[noise]
    return env


def installed_executables(install: Path = INSTALL) -> dict[str, list[str]]:
    """``{package: [executable, ...]}`` for every package of the workspace.

    Read from the install tree, where ``ros2 run`` looks (``lib/<package>/``).
    """
    found: dict[str, list[str]] = {}
    for package_dir in sorted(p for p in install.iterdir() if p.is_dir()):
        lib = package_dir / 'lib' / package_dir.name
        if lib.is_dir():
            found[package_dir.name] = sorted(
                f.name for f in lib.iterdir() if f.is_file() and os.access(f, os.X_OK))
    return found
