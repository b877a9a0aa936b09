"""`ros2 pkg create|list|prefix|executables|xml`: the packages of the ament index.

Packages are found through the ament index (AMENT_PREFIX_PATH); a package's
executables are the executable files in `<prefix>/lib/<package>/`, as for
`ros2 run`.  `create` lays out a new package (ros2_cleanroom.pkg_create).
"""
from __future__ import annotations

import argparse
import os
import xml.etree.ElementTree as ElementTree

from ros2_cleanroom.pkg_create import add_arguments, create_package
from ros2_cleanroom.verb_args import add_verb, command_parser, fail, run


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('pkg', 'Various package related sub-commands')
    add_arguments(add_verb(verbs, 'create', 'Create a new ROS 2 package', create_package))
    executables = add_verb(verbs, 'executables', 'Output a list of package specific executables',
                           list_executables)
    executables.add_argument('package_name', nargs='?', help='The package name')
    executables.add_argument('--full-path', action='store_true',
                             help='Show full path of each executable')
    add_verb(verbs, 'list', 'Output a list of available packages', list_packages)
    prefix = add_verb(verbs, 'prefix', 'Output the prefix path of a package', package_prefix)
    prefix.add_argument('package_name', help='The package name')
    prefix.add_argument('--share', action='store_true',
                        help='Show share directory for the package')
    manifest = add_verb(verbs, 'xml', 'Output the XML of the package manifest or a specific tag',
                        package_xml)
    manifest.add_argument('package_name', help='The package name')
    manifest.add_argument('-t', '--tag', help="The XML tag to output (e.g. 'version')")
    return parser


def _packages() -> dict[str, str]:
    from ament_index_python.packages import get_packages_with_prefixes
    return get_packages_with_prefixes()


def list_packages(args: argparse.Namespace) -> int:
    for name in sorted(_packages()):
        print(name)
    return 0


def package_prefix(args: argparse.Namespace) -> int:
    prefix = _packages().get(args.package_name)
    if prefix is None:
        return fail('Package not found')
    print(os.path.join(prefix, 'share', args.package_name) if args.share else prefix)
    return 0


def executables(package: str, prefix: str) -> list[str]:
    """Full paths of the package's executables, sorted by name."""
    libexec = os.path.join(prefix, 'lib', package)
    if not os.path.isdir(libexec):
        return []
    paths = (os.path.join(libexec, name) for name in sorted(os.listdir(libexec)))
    return [path for path in paths if os.path.isfile(path) and os.access(path, os.X_OK)]


def list_executables(args: argparse.Namespace) -> int:
    packages = _packages()
    if args.package_name is not None:
        if args.package_name not in packages:
            return fail(f"Package '{args.package_name}' not found")
        names = [args.package_name]
    else:
        names = sorted(packages)
    for package in names:
        for path in executables(package, packages[package]):
            print(path if args.full_path else f'{package} {os.path.basename(path)}')
    return 0


def package_xml(args: argparse.Namespace) -> int:
    prefix = _packages().get(args.package_name)
    if prefix is None:
        return fail('Package not found')
    root = ElementTree.parse(os.path.join(prefix, 'share', args.package_name,
                                          'package.xml')).getroot()
    if args.tag is None:
        print(ElementTree.tostring(root, encoding='unicode'))
        return 0
    found = root.findall(args.tag)
    if not found:
        return fail('XML tag not found')
    for element in found:
        print(element.text)
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
