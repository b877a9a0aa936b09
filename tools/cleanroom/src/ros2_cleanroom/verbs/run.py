"""`ros2 run PKG EXECUTABLE [args...]`: start one executable of a package.

The executable is looked up in `<prefix>/lib/<pkg>/` of the package's install
prefix (found through the ament index, i.e. AMENT_PREFIX_PATH) and run in the
foreground.  Messages, exit codes and signal handling follow ROS 2 Jazzy: a child that fails
makes us print `[ros2run]: Process exited with failure N` and exit with N.

This module deliberately imports nothing of `launch`: `ros2 run` is started a
lot (by lessons and tests) and should cost one interpreter start only.
"""
from __future__ import annotations

import argparse
import os
import shlex
import signal
import subprocess
import sys

from rclhelpers.processes import die_with_parent


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


def run_executable(cmd: list[str]) -> int:
    """Run `cmd` in the foreground and return its exit code.

    As Jazzy's ros2run: signals are not forwarded.  Ctrl-C in a terminal
    reaches the child directly (same process group), so SIGINT is ignored
    here (a no-op handler: the child, after exec, gets the default one) and
    we keep waiting for the child to finish.
    """
    parent = os.getpid()
    previous = signal.signal(signal.SIGINT, lambda _signum, _frame: None)
    try:
        process = subprocess.Popen(cmd, preexec_fn=lambda: die_with_parent(parent, signal.SIGTERM))
        return process.wait()
    finally:
        signal.signal(signal.SIGINT, previous)


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
