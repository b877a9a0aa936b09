"""Argument parsing shared by the `ros2 node|topic|param` verbs.

Each command is an argparse parser named like ros2cli's (`ros2 node`) with
one sub-parser per sub-verb, so unknown sub-verbs and bad arguments end in
argparse's usage error and exit code 2, as with ros2cli.
"""
from __future__ import annotations

import argparse
import sys
from collections.abc import Callable

from ros2_cleanroom.cli import CommandParser, usage_line

Handler = Callable[[argparse.Namespace], int]


def command_parser(command: str, description: str) -> tuple[argparse.ArgumentParser, object]:
    """The parser for `ros2 COMMAND` and the sub-parser group for its verbs."""
    parser = CommandParser(prog='ros2 ' + command, description=description)
    verbs = parser.add_subparsers(
        title='Commands', metavar=f'Call `ros2 {command} <command> -h` for more detailed usage.')
    parser.verbs = verbs
    return parser, verbs


def add_verb(verbs: object, name: str, help_text: str, handler: Handler) -> argparse.ArgumentParser:
    """Register a sub-verb whose `handler(args) -> exit code` runs it."""
    sub = verbs.add_parser(name, help=help_text, description=help_text)  # type: ignore[attr-defined]
    sub.set_defaults(handler=handler)
    return sub


def add_spin_time(parser: argparse.ArgumentParser) -> None:
    """`--spin-time` and `--no-daemon`, accepted as ros2cli accepts them.

    Without a daemon every command discovers the graph itself; `--spin-time`
    bounds how long it waits for discovery.
    """
    parser.add_argument('--spin-time', type=float, default=None,
                        help='Spin time in seconds to wait for discovery')
    parser.add_argument('--no-daemon', action='store_true',
                        help='Do not spawn nor use an already running daemon')


def run(parser: argparse.ArgumentParser, argv: list[str]) -> int:
    """Parse `argv` and run the chosen verb; no verb prints the help."""
    args, unknown = parser.parse_known_args(argv)
    if unknown:
        return unrecognized_arguments(unknown)
    handler = getattr(args, 'handler', None)
    if handler is None:
        parser.print_help()
        return 0
    try:
        return handler(args)
    except KeyboardInterrupt:
        return 0
    except BrokenPipeError:  # e.g. `ros2 topic echo /x | head -n 3`
        sys.stdout = None  # nothing more can be written; skip the flush at exit
        return 0


def unrecognized_arguments(unknown: list[str]) -> int:
    """Reject options a verb does not have (e.g. `param dump --output-dir`).

    ros2cli parses the whole command line with its top-level `ros2` parser,
    so it is that parser that reports them: its usage line, exit code 2.
    """
    print(usage_line(), file=sys.stderr)
    print(f"ros2: error: unrecognized arguments: {' '.join(unknown)}", file=sys.stderr)
    return 2


def fail(message: str) -> int:
    """Report an error the way ros2cli does for a failed verb: stderr, exit 1."""
    print(message, file=sys.stderr)
    return 1
