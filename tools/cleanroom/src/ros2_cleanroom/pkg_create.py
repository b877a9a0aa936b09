"""`ros2 pkg create`: lay out a new package as Jazzy does, printing what it creates.

The maintainer defaults to the login name (getpass: LOGNAME, USER, ...) and
the email to `git config user.email` (run where the command runs), else
`<maintainer>@todo.todo`.  The package name is not checked, as in Jazzy.
"""
from __future__ import annotations

import argparse
import getpass
import os
import subprocess
import sys

from ros2_cleanroom import pkg_cmake, pkg_sources

DEFAULT_DESCRIPTION = 'TODO: Package description'
DEFAULT_LICENSE = 'TODO: License declaration'


def git_email() -> str | None:
    """`git config user.email`, or None without git or without one."""
    try:
        done = subprocess.run(['git', 'config', 'user.email'], capture_output=True, text=True,
                              check=False)
    except OSError:
        return None
    email = done.stdout.strip()
    return email if done.returncode == 0 and email else None


class _Writer:
    """Creates folders and files under the package, reporting each as Jazzy does."""

    def __init__(self, root: str) -> None:
        self.root = root

    def folder(self, relative: str = '') -> None:
        path = os.path.join(self.root, relative) if relative else self.root
        print(f'creating folder {path}')
        os.makedirs(path)

    def file(self, relative: str, text: str, quiet: bool = False) -> None:
        path = os.path.join(self.root, relative)
        if not quiet:
            print(f'creating {path}')
        with open(path, 'w', encoding='utf-8') as stream:
            stream.write(text)


def _print_licenses() -> None:
    print('\n'.join(pkg_sources.LICENSES))


def _summary(args: argparse.Namespace, maintainer: str) -> None:
    print('going to create a new package')
    print(f'package name: {args.package_name}')
    print(f'destination directory: {os.path.abspath(args.destination_directory)}')
    print(f'package format: {args.package_format}')
    print('version: 0.0.0')
    print(f'description: {args.description}')
    print(f'maintainer: {[maintainer]}')
    print(f'licenses: {[args.license]}')
    print(f'build type: {args.build_type}')
    print(f'dependencies: {args.dependencies}')
    if args.node_name:
        print(f'node_name: {args.node_name}')
    if args.library_name:
        print(f'library_name: {args.library_name}')


def _python_package(out: _Writer, args: argparse.Namespace, name: str, email: str) -> None:
    package, node, library = args.package_name, args.node_name, args.library_name
    print('creating source folder')
    out.folder(package)
    out.file('setup.py', pkg_sources.setup_py(package, name, email, args.description,
                                              args.license, node))
    out.file('setup.cfg', pkg_sources.setup_cfg(package))
    out.folder('resource')
    out.file(os.path.join('resource', package), '')
    out.file(os.path.join(package, '__init__.py'), '')
    out.folder('test')
    for test in ('test_copyright.py', 'test_flake8.py', 'test_pep257.py'):
        out.file(os.path.join('test', test), pkg_sources.template(test + '.tmpl'))
    if node:
        out.file(os.path.join(package, node + '.py'), pkg_sources.python_node(package))
    if library:
        out.folder(os.path.join(package, library))
        out.file(os.path.join(package, library, '__init__.py'), '')


def _cmake_package(out: _Writer, args: argparse.Namespace) -> None:
    package, node, library = args.package_name, args.node_name, args.library_name
    deps = args.dependencies
    include = os.path.join('include', package)
    print('creating source and include folder')
    out.folder('src')
    out.folder(include)
    if args.build_type == 'ament_cmake':
        out.file('CMakeLists.txt', pkg_cmake.ament_cmake_lists(package, deps, node, library))
    else:
        out.file('CMakeLists.txt', pkg_cmake.plain_cmake_lists(package, deps, node, library))
        out.file(f'{package}Config.cmake.in', pkg_cmake.config_cmake_in(package, node, library))
        out.file(f'{package}ConfigVersion.cmake.in', pkg_cmake.config_version_cmake_in(package))
    if node:
        out.file(os.path.join('src', node + '.cpp'), pkg_sources.cpp_node(package))
    if library:
        out.file(os.path.join(include, library + '.hpp'),
                 pkg_sources.library_header(package, library))
        out.file(os.path.join('src', library + '.cpp'),
                 pkg_sources.library_source(package, library))
        out.file(os.path.join(include, 'visibility_control.h'),
                 pkg_sources.visibility_control(package))


def create_package(args: argparse.Namespace) -> int:
    """Run `ros2 pkg create` with its parsed arguments; the exit code."""
    if args.license == '?':
        print('Supported licenses:')
        _print_licenses()
        return 0
    if args.node_name and args.node_name == args.library_name:
        args.node_name += '_node'
        print('[WARNING] node name can not be equal to the library name', file=sys.stderr)
        print(f'[WARNING] renaming node to {args.node_name}', file=sys.stderr)
    root = os.path.join(args.destination_directory, args.package_name)
    if os.path.exists(root):
        print(f'\nAborted!\nThe directory already exists: {root}\nEither remove the directory '
              'or choose a different destination directory or package name', file=sys.stderr)
        return 1
    name = getpass.getuser() if args.maintainer_name is None else args.maintainer_name
    email = args.maintainer_email or git_email() or f'{name}@todo.todo'
    _summary(args, f'{name} <{email}>')
    out = _Writer(root)
    out.folder()
    out.file('package.xml', pkg_sources.package_xml(
        args.package_name, args.package_format, args.description, name, email, args.license,
        args.build_type, args.dependencies, args.library_name))
    if args.build_type == 'ament_python':
        _python_package(out, args, name, email)
    else:
        _cmake_package(out, args)
    if args.license in pkg_sources.LICENSES:
        out.file('LICENSE', pkg_sources.license_text(args.license), quiet=True)
        return 0
    print(f"\n[WARNING]: Unknown license '{args.license}'.  This has been set in the package.xml, "
          'but no LICENSE file has been created.\n'
          'It is recommended to use one of the ament license identifiers:')
    _print_licenses()
    return 0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """`ros2 pkg create`'s options, in Jazzy's order and words."""
    parser.add_argument('package_name', help='The package name')
    parser.add_argument('--package-format', '--package_format', type=int, choices=[2, 3],
                        default=3, help='The package.xml format.')
    parser.add_argument('--description', default=DEFAULT_DESCRIPTION,
                        help='The description given in the package.xml')
    parser.add_argument('--license', default=DEFAULT_LICENSE,
                        help='The license attached to this package; this can be an arbitrary '
                             'string, but a LICENSE file will only be generated if it is one of '
                             "the supported licenses (pass '?' to get a list)")
    parser.add_argument('--destination-directory', default=os.curdir,
                        help='Directory where to create the package directory')
    parser.add_argument('--build-type', default='ament_cmake',
                        choices=['cmake', 'ament_cmake', 'ament_python'],
                        help='The build type to process the package with')
    parser.add_argument('--dependencies', nargs='+', default=[], help='list of dependencies')
    parser.add_argument('--maintainer-email', help='email address of the maintainer of this '
                                                   'package')
    parser.add_argument('--maintainer-name', help='name of the maintainer of this package')
    parser.add_argument('--node-name', help='name of the empty executable')
    parser.add_argument('--library-name', help='name of the empty library')
