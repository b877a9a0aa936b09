"""`labkit.launch()`, `labkit.run()` and `labkit.start()`: start things in the background.

Each builds the exact command a student would type in a terminal (shown as
`.command`), finds the `ros2` executable of the active environment (a real
ROS 2 install or the project's own), and starts it as a :class:`Background`.
The command line of a launch and the text of its arguments are speccheck's
(`speccheck.launch_command`), which starts launches the same way.
"""
from __future__ import annotations

import os
import shlex
from collections.abc import Mapping, Sequence
from typing import Any

from speccheck.launch_command import format_argument, launch_words

from labkit.background import Background
from labkit.ros2_command import find_ros2


def _start_ros2(words: list[str], env: Mapping[str, str] | None,
                cwd: str | os.PathLike | None) -> Background:
    environment = dict(os.environ)
    environment.update(env or {})
    return Background([find_ros2(environment), *words[1:]], display=words, env=environment,
                      cwd=cwd)


def launch(package_or_file: str | os.PathLike, launch_file: str | None = None, /, *,
           launch_arguments: Mapping[str, Any] | None = None,
           env: Mapping[str, str] | None = None, cwd: str | os.PathLike | None = None,
           **arguments: Any) -> Background:
    """Start `ros2 launch` in the background and return the running launch.

    Examples::

        run = labkit.launch('my_robot_pkg', 'robot_system.launch.py', robot_name='my_bot')
        run.command    # 'ros2 launch my_robot_pkg robot_system.launch.py robot_name:=my_bot'

        with labkit.launch('my_robot_pkg', 'robot_system.launch.py') as run:
            run.wait_for_nodes(['/sensor_publisher', '/data_processor'])

    Keyword arguments become launch arguments (`name:=value`; True becomes
    `true`).  A launch argument whose name clashes with a parameter of this
    function goes in `launch_arguments={...}`.  `env` adds environment
    variables; the ROS isolation (ROS_DOMAIN_ID, discovery range) is
    inherited from the notebook.
    """
    words = launch_words(package_or_file, launch_file, {**(launch_arguments or {}), **arguments})
    return _start_ros2(words, env, cwd)


#: Same as :func:`launch`, for readers who prefer the explicit name.
start_launch = launch


def run(package: str, executable: str, *arguments: str,
        parameters: Mapping[str, Any] | None = None,
        remappings: Mapping[str, str] | None = None,
        name: str | None = None, namespace: str | None = None,
        env: Mapping[str, str] | None = None,
        cwd: str | os.PathLike | None = None) -> Background:
    """Start `ros2 run PACKAGE EXECUTABLE` in the background and return it.

    `parameters`, `remappings`, `name` and `namespace` become the usual
    `--ros-args -p name:=value -r from:=to -r __node:=... -r __ns:=...`
    so that `.command` shows students the full command line::

        node = labkit.run('my_robot_pkg', 'sensor_publisher', parameters={'publish_rate': 5.0})
        node.command   # 'ros2 run my_robot_pkg sensor_publisher --ros-args -p publish_rate:=5.0'
    """
    words = ['ros2', 'run', package, executable, *arguments]
    ros_args: list[str] = []
    if name:
        ros_args += ['-r', f'__node:={name}']
    if namespace:
        ros_args += ['-r', f'__ns:={namespace}']
    for key, value in (parameters or {}).items():
        ros_args += ['-p', f'{key}:={format_argument(value)}']
    for source, target in (remappings or {}).items():
        ros_args += ['-r', f'{source}:={target}']
    if ros_args:
        words += ['--ros-args', *ros_args]
    return _start_ros2(words, env, cwd)


def start(command: str | Sequence[str], *, env: Mapping[str, str] | None = None,
          cwd: str | os.PathLike | None = None) -> Background:
    """Start any command in the background (a string is split like a shell would).

    Use :func:`launch` and :func:`run` for ROS 2; this is for the rest, e.g.
    `labkit.start('ros2 topic echo /chatter')`.
    """
    words = shlex.split(command) if isinstance(command, str) else list(command)
    if words and words[0] == 'ros2':
        return _start_ros2(words, env, cwd)
    environment = dict(os.environ)
    environment.update(env or {})
    return Background(words, env=environment, cwd=cwd)
