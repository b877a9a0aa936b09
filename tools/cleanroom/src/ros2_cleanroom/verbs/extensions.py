"""`ros2 extensions` (hidden from `ros2 -h`, as in Jazzy): list the extensions.

The clean room's own commands and sub-verbs, derived by
ros2_cleanroom.extension_registry (its docstring says how), in Jazzy's shape:
each extension point's name on a line, then `  <name>: <description>` for each
of its extensions, both sorted by name.  Nothing fails to load here, so `--all`
adds no `- ` lines; `--verbose` ends after the first extension with Jazzy's
AttributeError (see extension_registry.verbose_details).
"""
from __future__ import annotations

import argparse

from ros2_cleanroom.extension_registry import extensions, verbose_details
from ros2_cleanroom.verb_args import run


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog='ros2 extensions', description='List extensions')
    parser.add_argument('--all', '-a', action='store_true',
                        help='Also show extensions which failed to load or are incompatible. '
                             '(prefixed with `- `)')
    parser.add_argument('--verbose', '-v', action='store_true',
                        help='Show more information for each extension')
    parser.set_defaults(handler=list_extensions)
    return parser


def list_extensions(args: argparse.Namespace) -> int:
    for group, entries in extensions().items():
        print(group)
        for entry_point, description in entries:
            print(f'  {entry_point.name}: {description}')
            if args.verbose:
                print(verbose_details(entry_point))
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
