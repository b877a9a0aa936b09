"""`ros2 launch`: run a launch file of a package, or a launch file given by path.

    ros2 launch PKG FILE [name:=value ...]
    ros2 launch PATH [name:=value ...]

Messages and exit codes follow ROS 2 Jazzy (see the conformance goldens):
errors about finding the file go to stderr with exit code 1; errors while
launching are logged by the launch system and give exit code 1.
"""
from __future__ import annotations

import argparse
import os
import sys

from ros2_cleanroom.verb_args import unrecognized_arguments


class CommandError(Exception):
    """An error reported on stderr with exit code 1, before anything is launched."""


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog='ros2 launch', description='Run a launch file')
    parser.add_argument('-n', '--noninteractive', action='store_true',
                        help='Run the launch system non-interactively, with no terminal '
                             'associated')
    parser.add_argument('-d', '--debug', action='store_true',
                        help='Put the launch system in debug mode, provides more verbose '
                             'output.')
    group = parser.add_mutually_exclusive_group()
    group.add_argument('-p', '--print', '--print-description', action='store_true',
                       help='Print the launch description to the console without launching '
                            'it.')
    group.add_argument('-s', '--show-args', '--show-arguments', action='store_true',
                       help='Show arguments that may be given to the launch file.')
    parser.add_argument('-a', '--show-all-subprocesses-output', action='store_true',
                        help="Show all launched subprocesses' output by overriding their "
                             'output configuration using the OVERRIDE_LAUNCH_PROCESS_OUTPUT '
                             'envvar.')
    parser.add_argument('--launch-prefix', metavar='LAUNCH_PREFIX',
                        help='Prefix command, which should go before all executables. '
                             'Command must be wrapped in quotes if it contains spaces '
                             "(e.g. --launch-prefix 'xterm -e gdb -ex run --args').")
    parser.add_argument('--launch-prefix-filter', metavar='LAUNCH_PREFIX_FILTER',
                        help='Regex pattern for filtering which executables the '
                             '--launch-prefix is applied to by matching the executable name.')
    parser.add_argument('package_name', help='Name of the ROS package which contains the '
                                             'launch file, or a path to a launch file')
    parser.add_argument('launch_file_name', nargs='?',
                        help='Name of the launch file')
    parser.add_argument('launch_arguments', nargs='*',
                        help="Arguments to the launch file; '<name>:=<value>' (for duplicates, "
                             'last one wins)')
    return parser


def find_launch_file_in_package(package: str, file_name: str) -> str:
    """Return the path of `file_name` anywhere below the package's share directory."""
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory

    try:
        share = get_package_share_directory(package)
    except PackageNotFoundError as exc:
        raise CommandError(f"Package '{package}' not found: {exc}") from exc
    matches = []
    for root, _dirs, files in os.walk(share):
        if file_name in files:
            matches.append(os.path.join(root, file_name))
    if not matches:
        raise CommandError(f"file '{file_name}' was not found in the share directory of "
                           f"package '{package}' which is at '{share}'")
    if len(matches) > 1:
        raise CommandError(f"multiple files named '{file_name}' found in the share directory "
                           f"of package '{package}': {sorted(matches)}")
    return matches[0]


def resolve_launch_file(args: argparse.Namespace) -> tuple[str, list[str]]:
    """Return (launch file path, launch argument strings) for PKG FILE or PATH forms."""
    if os.path.isfile(args.package_name):
        extra = [args.launch_file_name] if args.launch_file_name is not None else []
        return args.package_name, extra + list(args.launch_arguments)
    if args.launch_file_name is None:
        raise CommandError(f"no launch file '{args.package_name}' found, and no launch file "
                           'name given for a package')
    return (find_launch_file_in_package(args.package_name, args.launch_file_name),
            list(args.launch_arguments))


def parse_launch_arguments(arguments: list[str]) -> list[tuple[str, str]]:
    """Split `name:=value` items; anything else is an error naming the item."""
    parsed = []
    for argument in arguments:
        name, sep, value = argument.partition(':=')
        if not sep or not name:
            raise CommandError(f"malformed launch argument '{argument}', expected format "
                               "'<name>:=<value>'")
        parsed.append((name, value))
    return parsed


def format_launch_arguments(arguments: list) -> str:
    """The text of `--show-args` for DeclareLaunchArgument actions."""
    lines = ["Arguments (pass arguments as '<name>:=<value>'):"]
    if not arguments:
        lines += ['', '  No arguments.']
    for argument in arguments:
        lines += ['', f"    '{argument.name}':"]
        lines += ['        ' + line for line in argument.description.splitlines() or ['']]
        if argument.default_value is not None:
            default = ' + '.join(s.describe() for s in argument.default_value)
            lines.append(f'        (default: {default})')
    return '\n'.join(lines)


def _load_description(path: str) -> object:
    from launch.launch_description_sources import get_launch_description_from_any_launch_file

    return get_launch_description_from_any_launch_file(path)


def launch_a_launch_file(path: str, arguments: list[tuple[str, str]], *, debug: bool,
                         noninteractive: bool, launch_prefix: str | None,
                         launch_prefix_filter: str | None) -> int:
    """Run the launch file until it is done; return the launch's exit code."""
    import launch
    from launch.actions import IncludeLaunchDescription, SetLaunchConfiguration
    from launch.launch_description_sources import AnyLaunchDescriptionSource

    service = launch.LaunchService(argv=[f'{n}:={v}' for n, v in arguments],
                                   noninteractive=noninteractive, debug=debug)
    entities: list = []
    if launch_prefix:
        entities.append(SetLaunchConfiguration('launch-prefix', launch_prefix))
    if launch_prefix_filter:
        entities.append(SetLaunchConfiguration('launch-prefix-filter', launch_prefix_filter))
    entities.append(IncludeLaunchDescription(AnyLaunchDescriptionSource(path),
                                             launch_arguments=arguments))
    service.include_launch_description(launch.LaunchDescription(entities))
    return service.run()


def _stdin_is_a_terminal() -> bool:
    """Jazzy's `ros2 launch` runs non-interactively when standard input is no terminal.

    Observed on the reference: with stdin from /dev/null or a pipe, SIGINT to
    `ros2 launch` alone is sent on to every process at once, as `-n` does; with
    a terminal it is not (the terminal's Ctrl-C reached the whole group).
    """
    return sys.stdin is not None and sys.stdin.isatty()


def main(argv: list[str]) -> int:
    """Entry point of `ros2 launch`; returns the exit code."""
    args, unknown = _parser().parse_known_args(argv)
    if unknown:  # reported by ros2cli's top-level parser, as for every verb
        return unrecognized_arguments(unknown)
    try:
        path, raw_arguments = resolve_launch_file(args)
        arguments = parse_launch_arguments(raw_arguments)
        if args.show_args or args.print:
            description = _load_description(path)
            if args.show_args:
                print(format_launch_arguments(description.get_launch_arguments()))
            else:
                from launch import LaunchIntrospector

                print(LaunchIntrospector().format_launch_description(description))
            return 0
    except CommandError as exc:
        print(exc, file=sys.stderr)
        return 1
    except Exception as exc:  # noqa: BLE001 - a broken launch file while introspecting
        print(f'Error while loading the launch file: {exc}', file=sys.stderr)
        return 1
    if args.show_all_subprocesses_output:
        os.environ['OVERRIDE_LAUNCH_PROCESS_OUTPUT'] = 'both'
    return launch_a_launch_file(path, arguments, debug=args.debug,
                                noninteractive=args.noninteractive or not _stdin_is_a_terminal(),
                                launch_prefix=args.launch_prefix,
                                launch_prefix_filter=args.launch_prefix_filter)
