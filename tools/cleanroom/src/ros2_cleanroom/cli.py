"""Entry point of the `ros2` command: dispatch `ros2 VERB ...` to a verb module.

Each verb lives in `ros2_cleanroom.verbs.<verb>` and provides
`main(argv: list[str]) -> int`; it is imported only when used so that
`ros2 run` does not pay for importing the launch system.
"""
from __future__ import annotations

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
#: Commands that run another command's module.
ALIASES = {'wtf': 'doctor'}


def usage() -> str:
    lines = ['usage: ros2 [-h] Call `ros2 <command> -h` for more detailed usage. ...', '',
             'ros2 is an extensible command-line tool for ROS 2.', '',
             'Commands:']
    lines += [f'  {name:<9}  {text}' for name, text in sorted(VERBS.items())]
    lines += ['', '  Call `ros2 <command> -h` for more detailed usage.']
    return '\n'.join(lines)


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] in ('-h', '--help'):
        print(usage())
        return 0
    verb, rest = argv[0], argv[1:]
    if verb not in VERBS:
        print(usage().splitlines()[0], file=sys.stderr)
        choices = ', '.join(f"'{v}'" for v in sorted(VERBS))
        print("ros2: error: argument Call `ros2 <command> -h` for more detailed usage.: "
              f"invalid choice: '{verb}' (choose from {choices})", file=sys.stderr)
        return 2
    module = importlib.import_module('ros2_cleanroom.verbs.' + ALIASES.get(verb, verb))
    return module.main(rest)


if __name__ == '__main__':
    sys.exit(main())
