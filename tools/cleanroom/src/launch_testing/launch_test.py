"""The `launch_test` command: run one launch test file."""
from __future__ import annotations

import argparse
import logging
import os
import sys

from .domain_isolation import isolated_domain
from .junitxml import unittestResultsToXml
from .loader import LaunchTestError, LoadTestsFromPythonModule, load_module
from .parse_arguments import parse_launch_arguments
from .print_arguments import print_arguments_of_launch_description
from .test_runner import LaunchTestRunner

_logger = logging.getLogger('launch_test')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Add arguments to the CLI parser."""
    parser.add_argument('launch_test_file', help='Path to the launch test.')
    parser.add_argument('-v', '--verbose', action='store_true', default=False,
                        help='Run with verbose output')
    parser.add_argument('-s', '--show-args', '--show-arguments', action='store_true',
                        default=False, help='Show arguments that may be given to the test file.')
    parser.add_argument('launch_args', nargs='*',
                        help="Arguments to the launch file; '<name>:=<value>' (for duplicates, "
                             'last one wins)')
    parser.add_argument('--junit-xml', action='store', dest='xmlpath', default=None,
                        help='Do write xUnit reports to specified path.')
    parser.add_argument('--package-name', action='store', default=None,
                        help='Name of the package the test is in. Useful to aggregate xUnit '
                             'reports.')


def parse_arguments(argv: list[str] | None = None):
    """Return (parser, args) for `argv` (default: the command line)."""
    parser = argparse.ArgumentParser(description='Launch integration testing tool')
    add_arguments(parser)
    return parser, parser.parse_args(argv)


def run(parser: argparse.ArgumentParser, args, test_runner_cls=LaunchTestRunner) -> int:
    """Load the file, run its tests, write the JUnit report; 0 when everything passed."""
    if args.verbose:
        _logger.setLevel(logging.DEBUG)
    try:
        parse_launch_arguments(args.launch_args)
        module = load_module(args.launch_test_file)
        test_runs = LoadTestsFromPythonModule(
            module, name=f'{args.package_name}.{module.__name__}.launch_tests'
            if args.package_name else None)
    except LaunchTestError as exc:
        parser.error(str(exc))
    if args.show_args:
        for test_run in test_runs:
            description, _ = test_run.generate_description(lambda: None)
            print_arguments_of_launch_description(launch_description=description)
        return 0
    runner = test_runner_cls(test_runs=test_runs, launch_file_arguments=args.launch_args,
                             debug=args.verbose)
    try:
        runner.validate()
        results = runner.run()
    except LaunchTestError as exc:
        parser.error(str(exc))
    passed = all(active.wasSuccessful() and post.wasSuccessful()
                 for active, post in results.values())
    if args.xmlpath:
        test_results = {}
        for test_run, (active, post) in results.items():
            test_results[f'{test_run.name}.active'] = active
            test_results[f'{test_run.name}.post_shutdown'] = post
        folder = os.path.dirname(os.path.abspath(args.xmlpath))
        os.makedirs(folder, exist_ok=True)
        tree = unittestResultsToXml(name=args.package_name or 'launch_test',
                                    test_results=test_results)
        tree.write(args.xmlpath, encoding='utf-8', xml_declaration=True)
    return 0 if passed else 1


def main(argv: list[str] | None = None) -> int:
    """Entry point of `launch_test`."""
    logging.basicConfig()
    parser, args = parse_arguments(argv)
    with isolated_domain():
        return run(parser, args)


if __name__ == '__main__':
    sys.exit(main())
