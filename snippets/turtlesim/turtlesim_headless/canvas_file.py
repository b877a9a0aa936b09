"""Where the headless turtlesim keeps its picture, and how a notebook gets it.

The node rewrites one PNG whenever the picture changed (and at least once a
second).  Its place: ``$TURTLESIM_CANVAS_PNG`` if set, else
``$ROS_HOME/turtlesim/<node>-domain<ROS_DOMAIN_ID>.png`` (``ROS_HOME``
defaults to ``~/.ros``), so simulators in different domains never share one.

In a notebook::

    from turtlesim_headless.canvas_file import wait_for_canvas
    display(wait_for_canvas())
"""
from __future__ import annotations

import os
import time
from collections.abc import Mapping
from pathlib import Path

from PIL import Image

ENV_VARIABLE = 'TURTLESIM_CANVAS_PNG'


def canvas_path(node: str = '/turtlesim', env: Mapping[str, str] | None = None) -> Path:
    """The PNG of the simulator node ``node`` (its full name) in ``env``'s domain."""
    env = os.environ if env is None else env
    if env.get(ENV_VARIABLE):
        return Path(env[ENV_VARIABLE])
    ros_home = Path(env.get('ROS_HOME') or Path(env.get('HOME', '~')).expanduser() / '.ros')
    stem = node.strip('/').replace('/', '__') or 'turtlesim'
    return ros_home / 'turtlesim' / f"{stem}-domain{env.get('ROS_DOMAIN_ID') or 0}.png"


def wait_for_canvas(node: str = '/turtlesim', newer_than: float | None = None,
                    timeout: float = 10.0, path: Path | None = None) -> Image.Image:
    """The simulator's picture, written after ``newer_than`` (default: now).

    Waits (at most ``timeout`` seconds) for the node to write it, so what
    you get shows everything that happened before the call.
    """
    path = canvas_path(node) if path is None else Path(path)
    newer_than = time.time() if newer_than is None else newer_than
    deadline = time.monotonic() + timeout
    while True:
        try:
            if path.stat().st_mtime > newer_than:
                with Image.open(path) as image:
                    return image.copy()
        except FileNotFoundError:
            pass
        if time.monotonic() > deadline:
            raise TimeoutError(f'no turtlesim picture newer than {newer_than:.3f} in {path} after '
                               f'{timeout} s: is turtlesim_node ({node}) running in this '
                               f"ROS_DOMAIN_ID ({os.environ.get('ROS_DOMAIN_ID', 0)})?")
        time.sleep(0.05)
