"""A launch file started as a child process for the length of one check.

`speccheck live --launch` and `speccheck snapshot --launch` start `ros2 launch`
the way a terminal would, wait for the nodes the spec names, and stop it the
way Ctrl-C would.  The launch runs in a process group of its own, so that
stopping it reaches every node it started (they share the group), and it is
told to stop (SIGINT) if speccheck itself dies, so a killed check leaves no
robot software running behind it.
"""
from __future__ import annotations

import os
import signal
import subprocess
import tempfile
import time
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from rclhelpers.names import is_hidden
from rclhelpers.processes import die_with_parent, stop_group

from speccheck import observer
from speccheck.launch_command import (
    find_ros2,
    full_node_names,
    launch_words,
    node_list,
    with_output,
)
from speccheck.ros_error import RosError

#: (signal, seconds to wait for the group to empty): Ctrl-C first, as in a terminal.
STOP_ESCALATION = ((signal.SIGINT, 10.0), (signal.SIGTERM, 3.0), (signal.SIGKILL, 2.0))
#: Lines of the launch's output shown when it did not start what was waited for.
OUTPUT_TAIL = 20


def _stop_on_ctrl_c_and_with(parent: int) -> None:
    """In the child before exec: SIGINT does what it does in a terminal (a shell's
    background job, or a script's, inherits it ignored, and `ros2 launch` would then
    neither stop nor stop its nodes), and it comes when `parent` dies."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    die_with_parent(parent, signal.SIGINT)


class LaunchError(RosError):
    """The launch exited, or did not start the nodes waited for in time."""


class Launch:
    """`ros2 launch` running in its own process group; a context manager that stops it.

    Attributes:
        command: the command line as a person would type it.
        pid: process ID of `ros2 launch` (also its process group ID).
    """

    def __init__(self, package_or_file: str | os.PathLike, launch_file: str | None = None,
                 arguments: Mapping[str, Any] | None = None) -> None:
        words = launch_words(package_or_file, launch_file, arguments)
        self.command = ' '.join(words)
        # a file, not a pipe: nothing has to read it while the check runs
        descriptor, name = tempfile.mkstemp(prefix='speccheck-launch-', suffix='.log')
        self._log = Path(name)
        me = os.getpid()
        try:
            self._process = subprocess.Popen(
                [find_ros2(), *words[1:]], stdin=subprocess.DEVNULL, stdout=descriptor,
                stderr=subprocess.STDOUT, start_new_session=True,
                preexec_fn=lambda: _stop_on_ctrl_c_and_with(me))
        except BaseException:
            self._log.unlink()
            raise
        finally:
            os.close(descriptor)
        self.pid = self._process.pid

    def output(self, last: int | None = None) -> str:
        """What the launch printed so far; `last=N` keeps only the last N lines."""
        lines = self._log.read_text(errors='replace').splitlines()
        return '\n'.join(lines[-last:] if last else lines)

    def wait_for_nodes(self, names: Iterable[str], timeout: float = 20.0) -> list[str]:
        """Wait until every node in `names` is in the graph; return the visible nodes.

        Raises LaunchError, naming the missing nodes, the nodes that are there
        and the end of the launch's output, if the launch exits first or the
        time runs out.
        """
        wanted = full_node_names(names)
        deadline = time.monotonic() + timeout
        while True:
            present = observer.node_names(include_hidden=True)
            missing = [name for name in wanted if name not in present]
            visible = [name for name in present if not is_hidden(name)]
            if not missing:
                return visible
            if self._process.poll() is not None:
                raise LaunchError(self._explain(
                    f'`{self.command}` exited with code {self._process.returncode} while '
                    f'waiting for {node_list(missing)}.'))
            if time.monotonic() >= deadline:
                raise LaunchError(self._explain(
                    f'Timed out after {timeout:g} s waiting for {node_list(missing)} from '
                    f'`{self.command}`.\nNodes in the graph: '
                    f'{", ".join(visible) if visible else "none"}.'))
            time.sleep(0.1)

    def _explain(self, message: str) -> str:
        return with_output(message, self.output(last=OUTPUT_TAIL))

    def stop(self) -> int:
        """Stop the launch and everything it started (SIGINT to the group, then
        SIGTERM, then SIGKILL); return its exit code."""
        stop_group(self.pid, STOP_ESCALATION)
        self._log.unlink(missing_ok=True)
        return self._process.wait()

    def __enter__(self) -> Launch:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.stop()
