"""`ros2 interface list|package|packages|proto|show`: the interface types installed.

Everything comes from the ament index (`rosidl_interfaces` resources, i.e.
AMENT_PREFIX_PATH) and the interface files a package installs under
`share/<package>/<msg|srv|action>/`.  `show` prints the definition file as
written, with each field of a message type followed by that type's own
definition, one tab deeper.
"""
from __future__ import annotations

import argparse
import importlib
import os
import re
import sys

from ros2_cleanroom.interfaces import message_to_yaml
from ros2_cleanroom.verb_args import add_verb, command_parser, fail, run

KINDS = ('msg', 'srv', 'action')
#: Field types that have no definition of their own.
PRIMITIVES = frozenset({
    'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16', 'uint16',
    'int32', 'uint32', 'int64', 'uint64', 'string', 'wstring'})


def _add_kind_flags(parser: argparse.ArgumentParser, words: tuple[str, str, str]) -> None:
    parser.add_argument('-m', '--only-msgs', action='store_true', help=words[0])
    parser.add_argument('-s', '--only-srvs', action='store_true', help=words[1])
    parser.add_argument('-a', '--only-actions', action='store_true', help=words[2])


_PRINT_ONLY = ('Print out only the message types', 'Print out only the service types',
               'Print out only the action types')


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('interface', 'Show information about ROS interfaces')
    listing = add_verb(verbs, 'list', 'List all interface types available', list_interfaces)
    _add_kind_flags(listing, _PRINT_ONLY)
    package = add_verb(verbs, 'package',
                       'Output a list of available interface types within one package',
                       package_interfaces)
    package.add_argument('package_name', help="Name of the ROS package (e.g. 'example_interfaces')")
    _add_kind_flags(package, _PRINT_ONLY)
    packages = add_verb(verbs, 'packages', 'Output a list of packages that provide interfaces',
                        list_packages)
    _add_kind_flags(packages, ('Only list packages that generate messages',
                               'Only list packages that generate services',
                               'Only list packages that generate actions'))
    proto = add_verb(verbs, 'proto', 'Output an interface prototype', show_proto)
    proto.add_argument('type', help="Show an interface definition (e.g. "
                                    "'example_interfaces/msg/String')")
    proto.add_argument('--no-quotes', action='store_true',
                       help='if true output has no outer quotes.')
    show = add_verb(verbs, 'show', 'Output the interface definition', show_interface)
    show.set_defaults(parser=show)
    show.add_argument('type',
                      help="Show an interface definition (e.g. "
                           "'example_interfaces/msg/String'). Passing '-' reads the argument "
                           "from stdin (e.g. 'ros2 topic type /chatter | ros2 interface show -').")
    comments = show.add_mutually_exclusive_group()
    comments.add_argument('--all-comments', action='store_true',
                          help='Show all comments, including for nested interface definitions')
    comments.add_argument('--no-comments', action='store_true',
                          help='Show no comments or whitespace')
    return parser


# --- the ament index ------------------------------------------------------------------

def interface_packages() -> dict[str, dict[str, set[str]]]:
    """{package: {kind: {type names}}} of every package that installs interfaces."""
    from ament_index_python.resources import get_resource, get_resources

    found = {}
    for package in get_resources('rosidl_interfaces'):
        content, _ = get_resource('rosidl_interfaces', package)
        kinds: dict[str, set[str]] = {kind: set() for kind in KINDS}
        for line in content.splitlines():
            kind, _, filename = line.strip().partition('/')
            if kind in kinds and filename:
                kinds[kind].add(os.path.splitext(filename)[0])
        found[package] = kinds
    return found


def _selected(args: argparse.Namespace) -> list[str]:
    return _flagged(args) or list(KINDS)


def _flagged(args: argparse.Namespace) -> list[str]:
    flags = (args.only_msgs, args.only_srvs, args.only_actions)
    return [kind for kind, flag in zip(KINDS, flags, strict=True) if flag]


def list_interfaces(args: argparse.Namespace) -> int:
    packages = interface_packages()
    titles = {'msg': 'Messages:', 'srv': 'Services:', 'action': 'Actions:'}
    for kind in _selected(args):
        print(titles[kind])
        names = sorted(f'{package}/{kind}/{name}'
                       for package, kinds in packages.items() for name in kinds[kind])
        for name in names:
            print('    ' + name)
    return 0


def package_interfaces(args: argparse.Namespace) -> int:
    from ament_index_python.packages import PackageNotFoundError, get_package_prefix

    try:
        get_package_prefix(args.package_name)
    except (PackageNotFoundError, ValueError):
        return fail(f"Unknown package '{args.package_name}'")
    kinds = interface_packages().get(args.package_name, {})
    # as Jazzy's: the names in the order of one (unordered) set
    for name in {f'{args.package_name}/{kind}/{name}'
                 for kind in _selected(args) for name in kinds.get(kind, ())}:
        print(name)
    return 0


def list_packages(args: argparse.Namespace) -> int:
    packages = interface_packages()
    kind = next(iter(_flagged(args)), None)  # -m before -s before -a, as Jazzy's
    for package in sorted(packages):
        if kind is None or packages[package][kind]:
            print(package)
    return 0


# --- proto ----------------------------------------------------------------------------

def show_proto(args: argparse.Namespace) -> int:
    """The YAML of a default instance (a service's request, an action's goal)."""
    parts = args.type.split('/')
    module = importlib.import_module('.'.join(parts[:-1]))
    interface = getattr(module, parts[-1])
    kind = parts[-2] if len(parts) > 1 else ''
    if kind == 'srv':
        interface = interface.Request
    elif kind == 'action':
        interface = interface.Goal
    text = message_to_yaml(interface(), truncate_length=None)
    print(text if args.no_quotes else f'"{text}"')
    return 0


# --- show -----------------------------------------------------------------------------

class InterfaceError(Exception):
    """A type `show` cannot find, in Jazzy's words."""


def interface_file(name: str) -> tuple[str, str, str]:
    """`pkg/kind/Type` -> (package, kind, path of its definition file)."""
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory

    parts = name.split('/')
    if len(parts) != 3:
        raise InterfaceError(f"Invalid name '{name}'. Expected three parts separated by '/'")
    if not all(parts):
        raise InterfaceError(f"Invalid name '{name}'. Must not contain empty parts")
    package, kind, type_name = parts
    try:
        share = get_package_share_directory(package)
    except (PackageNotFoundError, ValueError):
        raise InterfaceError(f"Unknown package '{package}'") from None
    idl = os.path.join(share, kind, type_name + '.idl')
    if not os.path.isfile(idl):
        raise InterfaceError(f"Could not find the interface '{idl}'")
    return package, kind, os.path.join(share, kind, f'{type_name}.{kind}')


def _without_comment(line: str) -> str | None:
    """A line as Jazzy shows it without comments (None: not shown at all).

    Blank lines and comment lines with text go (`#` and `##` alone stay);
    after a field, the text of a `# ` comment goes but its `#` stays.
    Indented comment lines are shown as written.
    """
    line = line.rstrip()
    if not line or (line.startswith('#') and line.strip('#')):
        return None
    start = 0
    while (index := line.find('# ', start)) != -1:
        if line[:index].strip():
            return line[:index + 1]
        start = index + 1
    return line


def _nested_type(line: str, package: str) -> str | None:
    """`pkg/msg/Type` of the field a line declares, if its type has a definition."""
    code = line.split('#', 1)[0]
    tokens = code.split()
    if len(tokens) < 2 or '=' in ''.join(tokens[1:]):
        return None  # not a field, or a constant
    base = re.sub(r'\[.*\]$', '', tokens[0])
    if base.split('<=')[0] in PRIMITIVES:
        return None
    parts = base.split('/')
    if len(parts) == 1:
        return f'{package}/msg/{parts[0]}'
    if len(parts) == 2:
        return f'{parts[0]}/msg/{parts[1]}'
    return base


def definition_lines(name: str, depth: int = 0, comments: str = 'default') -> list[str]:
    """The lines `ros2 interface show` prints for `name` at nesting `depth`.

    `comments`: 'default' (the top level as written, nested ones stripped),
    'all' (every level as written) or 'none' (every level stripped).
    """
    package, _, path = interface_file(name)
    with open(path, encoding='utf-8') as stream:
        text = stream.read()
    keep_all = comments == 'all' or (comments == 'default' and depth == 0)
    lines = []
    for line in text.splitlines():
        shown = line if keep_all else _without_comment(line)
        if shown is None:
            continue
        lines.append(('\t' * depth + shown).rstrip())
        nested = _nested_type(line, package)
        if nested is not None:
            lines += definition_lines(nested, depth + 1, comments)
    return lines


def show_interface(args: argparse.Namespace) -> int:
    name = sys.stdin.read().strip() if args.type == '-' else args.type
    if not name:
        args.parser.error('the passed value is empty')  # exits with code 2
    comments = 'all' if args.all_comments else 'none' if args.no_comments else 'default'
    try:
        lines = definition_lines(name, comments=comments)
    except InterfaceError as error:
        return fail(str(error))
    for line in lines:
        print(line)
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
