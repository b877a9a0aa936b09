"""``python -m textbook build|serve|test|check|lab`` - what the Makefile runs.

- build: check and execute the lessons, build the site into site/ (strict);
- serve: the same, served on http://127.0.0.1:8000, rebuilt on changes;
- test:  the whole test suite (pytest on test_workers workers), pytest's exit code;
- check: only the lesson checks (metadata, includes, inline code), no kernel;
- lab:   JupyterLab on lessons/ with the book's kernel (textbook.lab);
- parity: every lesson on the clean room and on a real Jazzy, compared (textbook.parity).
"""
from __future__ import annotations

import argparse
import os
import sys

from . import paths, settings, workspace
from .lab import lab_arguments, write_settings


def _exec(*args: str) -> int:
    """Become ``python -m <args>`` in the repository root.

    Replacing this process (instead of starting a child) lets Ctrl+C and
    SIGTERM reach mkdocs or pytest directly, and passes their exit code on.
    """
    os.chdir(paths.ROOT)
    env = dict(os.environ, NO_MKDOCS_2_WARNING='1')
    os.execve(sys.executable, [sys.executable, '-m', *args], env)
    return 1  # not reached


def _mkdocs(*args: str) -> int:
    return _exec('mkdocs', *args, '-f', str(paths.MKDOCS_YML))


def build(_: argparse.Namespace) -> int:
    return _mkdocs('build', '--strict')


def serve(options: argparse.Namespace) -> int:
    print(f'serving the textbook on http://{options.address} (Ctrl+C stops)', flush=True)
    return _mkdocs('serve', '--strict', '--dev-addr', options.address)


def test(options: argparse.Namespace) -> int:
    # loadgroup: the site tests (xdist_group "site") share one worker and one site
    # build; everything else, lessons included, spreads over all workers.
    # --durations: every run (CI's too) names its slowest tests.
    workers = options.workers or str(settings.load().test_workers)
    return _exec('pytest', '-p', 'textbook.pytest_plugin', '-n', workers,
                 '--dist', 'loadgroup', '--durations=25', *options.pytest_args)


def check(_: argparse.Namespace) -> int:
    from .lessons import load_all

    try:
        lessons = load_all()
    except ValueError as error:
        print(error, file=sys.stderr)
        return 1
    print(f'{len(lessons)} lesson(s) pass metadata, include and inline-code checks')
    return 0


def lab(options: argparse.Namespace) -> int:
    # Built here, once, rather than by the first kernel while JupyterLab waits for it.
    print('building the snippets workspace (when it changed) ...', flush=True)
    workspace.ensure_built()
    print(f"JupyterLab on lessons/ at http://{options.address} with the book's kernel "
          f"(Ctrl+C stops)", flush=True)
    return _exec('jupyterlab', *lab_arguments(options.address, browser=not options.no_browser,
                                              folder=write_settings()))


def parity(options: argparse.Namespace) -> int:
    from . import parity as parity_command

    return parity_command.main(options.pytest_args)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog='python -m textbook', description=__doc__)
    commands = parser.add_subparsers(dest='command', required=True)
    building = commands.add_parser('build', help='build the site from executed lessons')
    building.set_defaults(run=build)
    serving = commands.add_parser('serve', help='build and serve the site, rebuild on changes')
    serving.add_argument('--address', default='127.0.0.1:8000')
    serving.set_defaults(run=serve)
    testing = commands.add_parser('test', help='run the test suite')
    testing.add_argument('--workers', '-n', default=None,
                         help='pytest-xdist workers (default: test_workers in pyproject.toml)')
    testing.set_defaults(run=test)
    commands.add_parser('check', help='check lessons without executing them').set_defaults(
        run=check)
    labbing = commands.add_parser('lab', help="JupyterLab on the lessons, in the book's kernel")
    labbing.add_argument('--address', default='127.0.0.1:8888')
    labbing.add_argument('--no-browser', action='store_true', help='do not open a browser')
    labbing.set_defaults(run=lab)
    parity_command = commands.add_parser(
        'parity', help='execute the lessons on both stacks and compare their outputs',
        add_help=False)
    parity_command.set_defaults(run=parity)
    # Unknown arguments of `test` go to pytest, e.g. `python -m textbook test -k lessons`.
    options, extra = parser.parse_known_args(argv)
    if extra and options.command not in ('test', 'parity'):
        parser.error(f"unrecognized arguments: {' '.join(extra)}")
    options.pytest_args = extra
    return options.run(options)


if __name__ == '__main__':
    sys.exit(main())
