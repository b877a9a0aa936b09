"""`ros2 doctor [--report]` (alias `ros2 wtf`): check the setup and the running graph.

Its one sub-verb, `ros2 doctor hello`, checks the network between hosts
(ros2_cleanroom.doctor_hello).  Called as `ros2 wtf`, the help and errors name
`ros2 wtf` and its description is the alias's, as in Jazzy.

The checks run in Jazzy's order (network, middleware, topic).  Their findings
are Python UserWarnings printed as `<file>: <line>: UserWarning: <message>` on
stderr, so `PYTHONWARNINGS=ignore` hides them as it does in Jazzy; errors
fail a check, warnings only with `--include-warnings`.  The summary goes to
stdout and the exit code is 0 even when a check failed, as in Jazzy.
"""
from __future__ import annotations

import argparse
import sys
import warnings
from collections.abc import Callable

from ros2_cleanroom import cli_node, doctor_graph, doctor_hello, doctor_report
from ros2_cleanroom.cli import VERBS
from ros2_cleanroom.doctor_graph import QosPair, TopicEndpoints
from ros2_cleanroom.verb_args import add_verb, command_parser, run

#: The graph must have been unchanged this long (s) before the checks run.
DOCTOR_QUIET_TIME = 1.0
#: Upper bound (s) for that wait.
DOCTOR_MAX_WAIT = 6.0

# (errors, warnings) of one check
Findings = tuple[list[str], list[str]]
Check = Callable[[list[TopicEndpoints], list[QosPair]], Findings]


def _network_check(topics: list[TopicEndpoints], pairs: list[QosPair]) -> Findings:
    """Nothing is checked beyond the interfaces being readable (see the report)."""
    return [], []


def _qos_check(topics: list[TopicEndpoints], pairs: list[QosPair]) -> Findings:
    return doctor_graph.qos_errors(pairs), []


def _topic_check(topics: list[TopicEndpoints], pairs: list[QosPair]) -> Findings:
    return [], doctor_graph.lonely_endpoint_warnings(topics)


#: (failed-module name, check), in the order Jazzy runs them.
CHECKS: list[tuple[str, Check]] = [
    ('network', _network_check),
    ('middleware', _qos_check),
    ('topic', _topic_check),
]


def build_parser(command: str = 'doctor') -> argparse.ArgumentParser:
    """`ros2 doctor`, or `ros2 wtf` (the same options and sub-verb)."""
    parser, verbs = command_parser(command, VERBS[command])
    report = parser.add_mutually_exclusive_group()
    report.add_argument('--report', '-r', action='store_true', help='Print all reports.')
    report.add_argument('--report-failed', '-rf', action='store_true',
                        help='Print reports of failed checks only.')
    parser.add_argument('--exclude-packages', '-ep', action='store_true',
                        help='Exclude package checks or report.')
    parser.add_argument('--include-warnings', '-iw', action='store_true',
                        help='Include warnings as failed checks. Warnings are ignored by '
                             'default.')
    parser.set_defaults(handler=doctor)
    doctor_hello.add_arguments(
        add_verb(verbs, 'hello', doctor_hello.HELP, doctor_hello.hello))
    return parser


def _show_warning(message: Warning | str, category: type[Warning], filename: str,
                  lineno: int, file: object = None, line: str | None = None) -> None:
    sys.stderr.write(f'{filename}: {lineno}: {category.__name__}: {message}\n')


def run_checks(topics: list[TopicEndpoints], pairs: list[QosPair],
               include_warnings: bool) -> list[str]:
    """Run every check, warn its findings; return the names of the failed modules."""
    failed = []
    with warnings.catch_warnings():
        warnings.showwarning = _show_warning
        for module, check in CHECKS:
            errors, notes = check(topics, pairs)
            for message in errors + notes:
                warnings.warn(message, UserWarning, stacklevel=1)
            if errors or (include_warnings and notes):
                failed.append(module)
    return failed


def summary(failed: list[str], total: int) -> str:
    """The lines after the warnings: all passed, or how many failed and which."""
    if not failed:
        return f'\nAll {total} checks passed\n'
    return f"\n{len(failed)}/{total} check(s) failed\n\nFailed modules: {' '.join(failed)}"


def doctor(args: argparse.Namespace) -> int:
    with cli_node.cli_node() as node:
        # Its findings name every endpoint, so it lets discovery settle longer
        # than a listing does (endpoints trickle in late on a loaded machine).
        cli_node.wait_for_graph(node, quiet=DOCTOR_QUIET_TIME, max_wait=DOCTOR_MAX_WAIT)
        topics = doctor_graph.snapshot(node)
    pairs = doctor_graph.qos_pairs(topics)
    if args.report:
        print(doctor_report.report(topics, pairs))
        return 0
    failed = run_checks(topics, pairs, args.include_warnings)
    if args.report_failed:
        if failed:
            print(doctor_report.report(topics, pairs, only=set(failed)))
        return 0
    print(summary(failed, len(CHECKS)))
    return 0


def main(argv: list[str], command: str = 'doctor') -> int:
    """`command` is the name it was called by: `doctor` or its alias `wtf`."""
    return run(build_parser(command), argv)
