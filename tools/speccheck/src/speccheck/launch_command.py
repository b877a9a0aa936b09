"""The `ros2 launch` command line as a person would type it, and the words of the
messages about a launch that is waited for.

speccheck starts launches with it (`speccheck live --launch`), and labkit's
`labkit.launch()` builds the same command line with it, so both show the exact
command a reader can paste into a terminal.
"""
from __future__ import annotations

import os
import shutil
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any


def format_argument(value: Any) -> str:
    """Python values as launch/ROS command-line text: True -> `true`, 2.0 -> `2.0`."""
    if isinstance(value, bool):
        return 'true' if value else 'false'
    if isinstance(value, (list, tuple)):
        return '[' + ', '.join(format_argument(item) for item in value) + ']'
    return str(value)


def launch_words(package_or_file: str | os.PathLike, launch_file: str | None = None,
                 arguments: Mapping[str, Any] | None = None) -> list[str]:
    """`ros2 launch PACKAGE FILE name:=value ...` (or `ros2 launch PATH ...`) as words."""
    words = ['ros2', 'launch', os.fspath(package_or_file)]
    if launch_file is not None:
        words.append(launch_file)
    return words + [f'{name}:={format_argument(value)}'
                    for name, value in (arguments or {}).items()]


def find_ros2(env: Mapping[str, str] | None = None) -> str:
    """The `ros2` a terminal with this environment would run.

    Falls back to the one next to this Python (a virtual environment that is not
    on PATH, e.g. a notebook kernel or a command started directly from it).
    """
    path = (env if env is not None else os.environ).get('PATH', os.defpath)
    found = shutil.which('ros2', path=path)
    if found:
        return found
    beside = Path(sys.executable).parent / 'ros2'
    if beside.exists():
        return str(beside)
    raise FileNotFoundError('no `ros2` command found on PATH nor next to '
                            f'{sys.executable}; is ROS 2 (or the project venv) set up?')


def full_node_names(names: Iterable[str]) -> list[str]:
    """Node names as the graph lists them: a missing leading slash added."""
    return [name if name.startswith('/') else '/' + name for name in names]


def node_list(names: list[str]) -> str:
    """'node /a' or 'nodes /a, /b', for messages about the nodes waited for."""
    return ('node ' if len(names) == 1 else 'nodes ') + ', '.join(names)


def with_output(message: str, output: str) -> str:
    """`message` followed by the end of the command's output, or that it printed nothing."""
    return f'{message}\nLast lines of its output:\n{output}' if output else \
        f'{message}\nIt printed nothing.'
