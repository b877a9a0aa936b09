"""`ros2 daemon start|stop|status`: the background process listing commands ask."""
from __future__ import annotations

import argparse

from ros2_cleanroom import daemon
from ros2_cleanroom.verb_args import add_verb, command_parser, run


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('daemon', 'Various daemon related sub-commands')
    starting = add_verb(verbs, 'start', "Start the daemon if it isn't running", start)
    starting.add_argument('--debug', '-d', action='store_true', help='Print debug messages')
    add_verb(verbs, 'status', 'Output the status of the daemon', status)
    add_verb(verbs, 'stop', 'Stop the daemon if it is running', stop)
    return parser


def start(args: argparse.Namespace) -> int:
    if daemon.is_running():
        print('The daemon is already running')
    elif daemon.start():
        print('The daemon has been started')
    return 0


def status(args: argparse.Namespace) -> int:
    print('The daemon is running' if daemon.is_running() else 'The daemon is not running')
    return 0


def stop(args: argparse.Namespace) -> int:
    print('The daemon has been stopped' if daemon.stop() else 'The daemon is not running')
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
