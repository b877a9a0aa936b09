"""Command line: `speccheck static|live SPEC [--launch PKG FILE | PATH] [n:=v ...]`.

The same as `python -m speccheck ...` (what labkit and the lessons run) and
as the `speccheck` console command of the distribution (tools/speccheck).

Exit codes: 0 every requirement met, 1 some requirement not met, 2 bad input.
"""
from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from speccheck.cli_targets import TargetError, find_launch_file, split_arguments
from speccheck.live_check import DEFAULT_WINDOW
from speccheck.spec import SpecError, load_spec


def build_parser(prog: str = 'python -m speccheck') -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog=prog,
        description='Check a ROS 2 launch file (static) or a running system (live) '
                    'against a spec file.')
    parser.add_argument('mode', choices=['static', 'live'],
                        help='static: read the launch file, start nothing; live: check the '
                             'running graph (after starting the launch file, if one is given)')
    parser.add_argument('spec', help='the spec file (YAML)')
    parser.add_argument('--launch', nargs=2, metavar=('PKG', 'FILE'),
                        help='a launch file installed in a package, as `ros2 launch PKG FILE`')
    parser.add_argument('--window', type=float, default=DEFAULT_WINDOW,
                        help=f'seconds to measure topic rates (live; default {DEFAULT_WINDOW:g})')
    parser.add_argument('--timeout', type=float, default=20.0,
                        help="seconds to wait for the spec's nodes after starting a launch "
                             '(live; default 20)')
    parser.add_argument('rest', nargs='*', metavar='PATH | name:=value',
                        help='a launch file path (instead of --launch), then launch arguments')
    return parser


def main(argv: Sequence[str] | None = None, prog: str = 'python -m speccheck') -> int:
    parser = build_parser(prog)
    options = parser.parse_intermixed_args(argv)
    try:
        spec = load_spec(options.spec)
        path_words, arguments = split_arguments(options.rest)
        launch_file = find_launch_file(options.launch, path_words)
    except (SpecError, TargetError) as error:
        print(f'speccheck: error: {error}', file=sys.stderr)
        return 2
    if options.mode == 'static':
        if launch_file is None:
            print('speccheck: error: static needs a launch file: --launch PKG FILE or a path',
                  file=sys.stderr)
            return 2
        from speccheck.static_check import check_static
        report = check_static(spec, launch_file, arguments)
    else:
        from speccheck.live_run import check_launch_live
        target = tuple(options.launch) if options.launch else launch_file
        report = check_launch_live(spec, target, arguments, window=options.window,
                                   timeout=options.timeout)
    print(report)
    return report.exit_code


def console() -> None:
    """The `speccheck` console command (pyproject's [project.scripts])."""
    sys.exit(main(prog='speccheck'))


if __name__ == '__main__':
    sys.exit(main())
