"""Entry point of the `ros2` command: dispatch `ros2 VERB ...` to a verb module.

Each verb lives in `ros2_cleanroom.verbs.<verb>` and provides
`main(argv: list[str]) -> int`; it is imported only when used so that
`ros2 run` does not pay for importing the launch system.
"""
from __future__ import annotations

import argparse
import importlib
import sys

VERBS = {
    'action': 'Various action related sub-commands',
    'component': 'Various component related sub-commands',
    'daemon': 'Various daemon related sub-commands',
    'doctor': 'Check ROS setup and other potential issues',
    'interface': 'Show information about ROS interfaces',
    'launch': 'Run a launch file',
    'lifecycle': 'Various lifecycle related sub-commands',
    'multicast': 'Various multicast related sub-commands',
    'node': 'Various node related sub-commands',
    'param': 'Various param related sub-commands',
    'pkg': 'Various package related sub-commands',
    'run': 'Run a package specific executable',
    'service': 'Various service related sub-commands',
    'topic': 'Various topic related sub-commands',
    'wtf': 'Use `wtf` as alias to `doctor`',
}
#: Commands Jazzy has but leaves out of `ros2 -h` (its invalid-choice list and
#: `ros2 extensions` name them).
HIDDEN_VERBS = {
    'extension_points': 'List extension points',
    'extensions': 'List extensions',
}
#: Every command `ros2` runs, shown or hidden.
COMMANDS = {**VERBS, **HIDDEN_VERBS}
#: Commands that run another command's module.
ALIASES = {'wtf': 'doctor'}


class CommandParser(argparse.ArgumentParser):
    """`ros2 COMMAND -h` as ros2cli prints it: the sub-verbs sorted by name in one
    aligned `Commands:` block, then the hint line."""

    verbs: argparse.Action | None = None

    def format_help(self) -> str:
        head = super().format_help().split('\nCommands:\n')[0]
        if self.verbs is None:
            return head
        entries = sorted((choice.dest, choice.help or '')
                         for choice in self.verbs._choices_actions)  # type: ignore[attr-defined]
        width = max((len(name) for name, _ in entries), default=0)
        block = '\n'.join(f'  {name:<{width}}  {text}' for name, text in entries)
        return (f'{head}\nCommands:\n{block}\n\n'
                f'  Call `{self.prog} <command> -h` for more detailed usage.\n')


#: ros2cli's words for its one top-level option.
_BUFFERING_HELP = ('Do not force line buffering in stdout and instead use the python default '
                   'buffering, which might be affected by PYTHONUNBUFFERED/-u and depends on '
                   'whatever stdout is interactive or not')
_BUFFERING = '--use-python-default-buffering'


def _parser() -> argparse.ArgumentParser:
    """The top-level parser, for its help and usage (argparse wraps them to the terminal)."""
    parser = CommandParser(prog='ros2',
                           description='ros2 is an extensible command-line tool for ROS 2.')
    parser.add_argument(_BUFFERING, action='store_true', help=_BUFFERING_HELP)
    commands = parser.add_subparsers(
        title='Commands', metavar='Call `ros2 <command> -h` for more detailed usage.')
    parser.verbs = commands
    for name in sorted(COMMANDS):  # a parser without help has no line in the help
        if name in VERBS:
            commands.add_parser(name, help=VERBS[name], add_help=False)
        else:
            commands.add_parser(name, add_help=False)
    return parser


def usage() -> str:
    """`ros2 -h`."""
    return _parser().format_help().rstrip('\n')


def usage_line() -> str:
    """The `usage: ros2 ...` lines that start each of ros2cli's error messages."""
    return _parser().format_usage().rstrip('\n')


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    while argv[:1] == [_BUFFERING]:  # accepted; output is line-buffered either way here
        argv = argv[1:]
    if not argv or argv[0] in ('-h', '--help'):
        print(usage())
        return 0
    verb, rest = argv[0], argv[1:]
    if verb not in COMMANDS:
        print(usage_line(), file=sys.stderr)
        choices = ', '.join(f"'{v}'" for v in sorted(COMMANDS))
        print("ros2: error: argument Call `ros2 <command> -h` for more detailed usage.: "
              f"invalid choice: '{verb}' (choose from {choices})", file=sys.stderr)
        return 2
    if verb in ALIASES:  # the alias's own name shows in its help and errors
        return importlib.import_module('ros2_cleanroom.verbs.' + ALIASES[verb]).main(rest, verb)
    return importlib.import_module('ros2_cleanroom.verbs.' + verb).main(rest)


if __name__ == '__main__':
    sys.exit(main())
