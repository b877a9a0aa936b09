"""`ros2 extension_points` (hidden from `ros2 -h`, as in Jazzy): list the extension points.

The list is the clean room's own, derived from its commands and their sub-verbs
by ros2_cleanroom.extension_registry (its docstring says how); each line is
`<name>: <description>`, sorted by name, as Jazzy prints them.  Nothing fails
to import here, so `--all` adds no `- ` lines; `--verbose` ends after the first
line with Jazzy's AttributeError (see extension_registry.verbose_details).
"""
from __future__ import annotations

import argparse

from ros2_cleanroom.extension_registry import extension_points, verbose_details
from ros2_cleanroom.verb_args import run


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog='ros2 extension_points',
                                     description='List extension points')
    parser.add_argument('--all', '-a', action='store_true',
                        help='Also show extension points which failed to be imported. '
                             '(prefixed with `- `)')
    parser.add_argument('--verbose', '-v', action='store_true',
                        help='Show more information for each extension point')
    parser.set_defaults(handler=list_extension_points)
    return parser


def list_extension_points(args: argparse.Namespace) -> int:
    for entry_point, description in extension_points():
        print(f'{entry_point.name}: {description}')
        if args.verbose:
            print(verbose_details(entry_point))
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
