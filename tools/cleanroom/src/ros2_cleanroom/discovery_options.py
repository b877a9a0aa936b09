"""The discovery options Jazzy's newer verbs share, worded as `ros2 ... -h` shows them.

`--spin-time` bounds the wait for discovery when no daemon answers; `-s`
is accepted as Jazzy accepts it (the verbs here read no clock); `--no-daemon`
keeps a listing away from the daemon.
"""
from __future__ import annotations

import argparse


def add_discovery_options(parser: argparse.ArgumentParser, no_daemon: bool = True) -> None:
    """`--spin-time`, `-s/--use-sim-time` and (unless `no_daemon` is False) `--no-daemon`."""
    parser.add_argument('--spin-time', type=float, default=None,
                        help='Spin time in seconds to wait for discovery (only applies when '
                             'not using an already running daemon)')
    parser.add_argument('-s', '--use-sim-time', action='store_true',
                        help='Enable ROS simulation time')
    if no_daemon:
        parser.add_argument('--no-daemon', action='store_true',
                            help='Do not spawn nor use an already running daemon')
