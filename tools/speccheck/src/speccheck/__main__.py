"""Command line: `speccheck static|live SPEC [--launch PKG FILE | PATH] [n:=v ...]
[--format text|json|junit|sarif]`, and `speccheck snapshot OUT [--launch PKG FILE |
PATH] [n:=v ...]`, which writes a spec from the running graph.

The same as `python -m speccheck ...` (what labkit and the lessons run) and
as the `speccheck` console command of the distribution (tools/speccheck).

Exit codes (EXIT_CODES): 0 every requirement met, 1 some requirement not met,
2 could not judge (a spec, launch file or argument it cannot use, or speccheck
itself failed): CI can tell a broken system from a broken check.
"""
from __future__ import annotations

import argparse
import sys
import traceback
from collections.abc import Sequence
from pathlib import Path

from speccheck.cli_targets import TargetError, find_launch_file, split_arguments
from speccheck.formats import FORMATS, render
from speccheck.live_check import DEFAULT_WINDOW
from speccheck.report import Report
from speccheck.spec import Spec, SpecError, load_spec

#: exit code -> meaning (printed by --help; docs/reference/spec-files.md says the same)
EXIT_CODES = {
    0: 'met: every requirement met (some may be "not checked")',
    1: 'not met: at least one requirement failed',
    2: 'could not judge: the spec file, launch file or arguments cannot be used, '
       'or speccheck itself failed',
}


def build_parser(prog: str = 'python -m speccheck') -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog=prog,
        description='Check a ROS 2 launch file (static) or a running system (live) '
                    'against a spec file.',
        epilog='exit codes: ' + '; '.join(f'{code} {meaning}'
                                          for code, meaning in EXIT_CODES.items()))
    parser.add_argument('mode', choices=['static', 'live', 'snapshot'],
                        help='static: read the launch file, start nothing; live: check the '
                             'running graph (after starting the launch file, if one is '
                             'given); snapshot: write SPEC from the running graph (after '
                             'starting the launch file and waiting for its graph to settle, '
                             'if one is given)')
    parser.add_argument('spec', help='the spec file (YAML); for snapshot the file to write, '
                                     '- for stdout')
    parser.add_argument('--launch', nargs=2, metavar=('PKG', 'FILE'),
                        help='a launch file installed in a package, as `ros2 launch PKG FILE`')
    parser.add_argument('--window', type=float, default=DEFAULT_WINDOW,
                        help=f'seconds to measure topic rates (live; default {DEFAULT_WINDOW:g})')
    parser.add_argument('--timeout', type=float, default=20.0,
                        help="seconds to wait for the spec's nodes (live) or for the graph "
                             'to settle (snapshot) after starting a launch (default 20)')
    parser.add_argument('--format', choices=FORMATS, default='text',
                        help='text (default: one line per requirement), json, junit (JUnit XML, '
                             'a testcase per requirement) or sarif (SARIF 2.1.0, results on the '
                             "spec file's lines, for GitHub code scanning); on exit code 2 "
                             'nothing is printed on stdout')
    parser.add_argument('rest', nargs='*', metavar='PATH | name:=value',
                        help='a launch file path (instead of --launch), then launch arguments')
    return parser


def main(argv: Sequence[str] | None = None, prog: str = 'python -m speccheck') -> int:
    parser = build_parser(prog)
    options = parser.parse_intermixed_args(argv)
    if options.mode == 'snapshot':
        return _snapshot(options)
    try:
        spec = load_spec(options.spec)
        path_words, arguments = split_arguments(options.rest)
        launch_file = find_launch_file(options.launch, path_words)
    except (SpecError, TargetError) as error:
        print(f'speccheck: error: {error}', file=sys.stderr)
        return 2
    if options.mode == 'static' and launch_file is None:
        print('speccheck: error: static needs a launch file: --launch PKG FILE or a path',
              file=sys.stderr)
        return 2
    try:
        report = _check(options, spec, launch_file, arguments)
    except Exception as error:  # a crash must not look like a verdict (exit 1)
        traceback.print_exc()
        print(f'speccheck: error: could not judge: {type(error).__name__}: {error}',
              file=sys.stderr)
        return 2
    print(render(report, options.format))
    return report.exit_code


def _snapshot(options: argparse.Namespace) -> int:
    """Write the spec of the running system (0), or say why not (2)."""
    try:
        path_words, arguments = split_arguments(options.rest)
        launch_file = find_launch_file(options.launch, path_words)
    except TargetError as error:
        print(f'speccheck: error: {error}', file=sys.stderr)
        return 2
    from speccheck.snapshot import SnapshotError, snapshot_launch, to_yaml
    target = tuple(options.launch) if options.launch else launch_file
    try:
        text = to_yaml(*snapshot_launch(target, arguments, timeout=options.timeout))
    except SnapshotError as error:
        print(f'speccheck: error: {error}', file=sys.stderr)
        return 2
    except Exception as error:  # as for a check: a crash is not a result
        traceback.print_exc()
        print(f'speccheck: error: no snapshot: {type(error).__name__}: {error}',
              file=sys.stderr)
        return 2
    if options.spec == '-':
        sys.stdout.write(text)
    else:
        Path(options.spec).write_text(text, encoding='utf-8')
        print(f'speccheck snapshot: wrote {options.spec}', file=sys.stderr)
    return 0


def _check(options: argparse.Namespace, spec: Spec, launch_file: Path | None,
           arguments: dict[str, str]) -> Report:
    if options.mode == 'static':
        from speccheck.static_check import check_static
        return check_static(spec, launch_file, arguments)
    from speccheck.live_run import check_launch_live
    target = tuple(options.launch) if options.launch else launch_file
    return check_launch_live(spec, target, arguments, window=options.window,
                             timeout=options.timeout)


def console() -> None:
    """The `speccheck` console command (pyproject's [project.scripts])."""
    sys.exit(main(prog='speccheck'))


if __name__ == '__main__':
    sys.exit(main())
