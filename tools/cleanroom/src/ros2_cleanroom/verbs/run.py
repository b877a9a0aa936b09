"""`ros2 run PKG EXECUTABLE [args...]`: start one executable of a package.

The executable is looked up in `<prefix>/lib/<pkg>/` of the package's install
prefix (found through the ament index, i.e. AMENT_PREFIX_PATH) and run in the
foreground.  Messages and exit codes follow ROS 2 Jazzy: a child that fails
makes us print `[ros2run]: Process exited with failure N` and exit with N.

This module deliberately imports nothing of `launch`: `ros2 run` is started a
lot (by lessons and tests) and should cost one interpreter start only.
"""
from __future__ import annotations

import argparse
import ctypes
import os
import shlex
import signal
import subprocess
import sys

_PR_SET_PDEATHSIG = 1


def _die_with_parent(parent_pid: int) -> None:
    """Runs in the child before exec: die if `ros2 run` dies, so nothing is orphaned."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        return
    if os.getppid() != parent_pid:  # the parent died before prctl took effect
        os._exit(1)


def find_executable(package: str, executable: str) -> str | None:
    """Return the path of `executable` in the package's libexec folder, or None.

    Raises ament_index_python's PackageNotFoundError when the package is unknown.
    """
    from ament_index_python.packages import get_package_prefix

    libexec = os.path.join(get_package_prefix(package), 'lib', package)
    candidate = os.path.join(libexec, executable)
    if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
        return candidate
    return None


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog='ros2 run', description='Run a package specific executable')
    parser.add_argument('--prefix', metavar='PREFIX',
                        help='Prefix command, which should go before the executable. '
                             'Command must be wrapped in quotes if it contains spaces '
                             "(e.g. --prefix 'gdb -ex run --args').")
    parser.add_argument('package_name', help='Name of the ROS package')
    parser.add_argument('executable_name', help='Name of the executable')
    parser.add_argument('argv', nargs=argparse.REMAINDER,
                        help='Pass arbitrary arguments to the executable')
    return parser


def _terminal_delivers_sigint() -> bool:
    """True when Ctrl-C on our terminal already reaches the child (same foreground group)."""
    try:
        return os.tcgetpgrp(sys.stdin.fileno()) == os.getpgrp()
    except (OSError, ValueError, AttributeError):
        return False


def run_executable(cmd: list[str]) -> int:
    """Run `cmd` in the foreground, forwarding SIGINT/SIGTERM, and return its exit code."""
    parent = os.getpid()
    process = subprocess.Popen(cmd, preexec_fn=lambda: _die_with_parent(parent))

    def forward(signum: int, _frame: object) -> None:
        if signum == signal.SIGINT and _terminal_delivers_sigint():
            return  # the terminal sent it to the child as well; do not send it twice
        try:
            process.send_signal(signum)
        except ProcessLookupError:
            pass

    previous = {s: signal.signal(s, forward) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        while True:
            try:
                return process.wait()
            except InterruptedError:
                continue
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)


def main(argv: list[str]) -> int:
    """Entry point of `ros2 run`; returns the exit code of the command."""
    args = _parser().parse_args(argv)
    from ament_index_python.packages import PackageNotFoundError

    try:
        path = find_executable(args.package_name, args.executable_name)
    except PackageNotFoundError:
        print(f"Package '{args.package_name}' not found", file=sys.stderr)
        return 1
    if path is None:
        print('No executable found', file=sys.stderr)
        return 1
    cmd = shlex.split(args.prefix) if args.prefix else []
    cmd += [path, *args.argv]
    returncode = run_executable(cmd)
    if returncode != 0:
        sys.stdout.flush()
        if returncode < 0 and -returncode in signal.valid_signals():
            print(f'[ros2run]: {signal.strsignal(-returncode)}', flush=True)
        else:
            print(f'[ros2run]: Process exited with failure {returncode}', flush=True)
    return returncode
