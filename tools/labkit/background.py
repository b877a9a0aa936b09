"""A command (usually `ros2 launch` or `ros2 run`) running in the background.

Lessons start a launch, look at it, then stop it, all from notebook cells.
The process gets a session of its own, so that stopping it reaches every
node it started (they share its process group), a pseudo-terminal as its
standard input, as in a student's shell, and a watchdog sidecar so that it
cannot outlive a kernel that crashes or is killed.
"""
from __future__ import annotations

import atexit
import os
import pty
import re
import shlex
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Iterable, Sequence
from pathlib import Path

from rclhelpers.names import is_hidden
from speccheck.launch_command import full_node_names, node_list, with_output

from labkit import observer
from labkit.errors import LabkitError, NodesNotFoundError, ProcessExitedError
from labkit.ros2_command import find_ros2, missing_from_daemon
from labkit.watchdog import stop_group

WATCHDOG = str(Path(__file__).with_name('watchdog.py'))
#: Seconds given to each signal of the shutdown sequence before escalating.
SIGINT_GRACE = 10.0
SIGTERM_GRACE = 3.0


_running: set[Background] = set()
_running_lock = threading.Lock()


class Background:
    """A command running in the background, with its output captured.

    Use it as a context manager, or call :meth:`stop` yourself; anything
    still running when the Python process exits is stopped too.

    Attributes:
        command: the command line as a student would type it, for display.
        pid: process ID of the command (also its process group ID).
    """

    def __init__(self, argv: Sequence[str], *, display: Sequence[str] | None = None,
                 env: dict[str, str] | None = None, cwd: str | os.PathLike | None = None,
                 ) -> None:
        self.argv = list(argv)
        self.command = shlex.join(display or argv)
        self._lines: list[str] = []
        self._output_changed = threading.Condition()
        self._returncode: int | None = None
        self._stopped = False
        environment = dict(os.environ if env is None else env)
        environment.setdefault('PYTHONUNBUFFERED', '1')  # output arrives as it is printed
        # A terminal as stdin: Jazzy's `ros2 launch` is then interactive, as in a
        # shell, and leaves SIGINT to the terminal's Ctrl-C (stop() sends it to the
        # group); without one it runs `--noninteractive` and sends every node a second
        # SIGINT of its own.  Nothing reads it; output stays on the pipe.
        self._terminal, terminal_side = pty.openpty()
        try:
            self._process = subprocess.Popen(
                self.argv, env=environment, cwd=cwd, stdin=terminal_side,
                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors='replace',
                start_new_session=True)
        except BaseException:
            os.close(self._terminal)
            raise
        finally:
            os.close(terminal_side)
        self.pid = self._process.pid
        self._reader = threading.Thread(target=self._read_output, daemon=True,
                                        name=f'labkit-output-{self.pid}')
        self._reader.start()
        # Run by path, not `-m labkit.watchdog`: it needs only psutil, and
        # importing the labkit package (rclpy, matplotlib) would slow it down.
        self._watchdog = subprocess.Popen(
            [sys.executable, WATCHDOG, str(os.getpid()), str(self.pid)],
            env=environment, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            start_new_session=True)
        with _running_lock:
            _running.add(self)

    # -- output ---------------------------------------------------------
    def _read_output(self) -> None:
        for line in self._process.stdout:
            with self._output_changed:
                self._lines.append(line.rstrip('\n'))
                self._output_changed.notify_all()
        with self._output_changed:
            self._output_changed.notify_all()

    @property
    def lines(self) -> list[str]:
        """Every line the command printed so far (stdout and stderr together)."""
        with self._output_changed:
            return list(self._lines)

    def output(self, last: int | None = None, *, since: str | None = None,
               until: str | None = None) -> str:
        """The captured output as text.

        `last=N` keeps only the last N lines; `since=` starts at the first line
        matching that regular expression, `until=` ends at the first line matching
        it after that (both included).  A lesson shows a stretch of a log that
        does not depend on how long it ran: the start up to a line it waited
        for, or the shutdown from Ctrl+C on.
        """
        lines = self.lines
        if since is not None:
            start = next((i for i, line in enumerate(lines) if re.search(since, line)), None)
            lines = lines[start:] if start is not None else []
        if until is not None:
            end = next((i for i, line in enumerate(lines) if re.search(until, line)), None)
            lines = lines[:end + 1] if end is not None else lines
        return '\n'.join(lines[-last:] if last else lines)

    def wait_for_output(self, pattern: str, timeout: float = 10.0) -> str:
        """Wait until a line matches the regular expression `pattern`; return that line."""
        regex = re.compile(pattern)
        deadline = time.monotonic() + timeout
        seen = 0
        with self._output_changed:
            while True:
                for line in self._lines[seen:]:
                    if regex.search(line):
                        return line
                seen = len(self._lines)
                if self.poll() is not None and not self._reader.is_alive():
                    raise ProcessExitedError(self._explain(
                        f'`{self.command}` exited with code {self.returncode} before printing '
                        f'a line matching {pattern!r}.'))
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    raise LabkitError(self._explain(
                        f'No line matching {pattern!r} after {timeout:g} s of `{self.command}`.'))
                self._output_changed.wait(min(remaining, 0.2))

    # -- state ----------------------------------------------------------
    def poll(self) -> int | None:
        """The exit code if the command has ended, else None."""
        if self._returncode is None:
            self._returncode = self._process.poll()
        return self._returncode

    @property
    def running(self) -> bool:
        return self.poll() is None

    @property
    def returncode(self) -> int | None:
        return self.poll()

    def wait(self, timeout: float = 60.0) -> int:
        """Wait until the command ends by itself (a launch that shut itself down);
        return its exit code.  If it is still running after `timeout` seconds, it is
        stopped and the error says so, with the end of its output."""
        try:
            self._process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.stop()
            raise LabkitError(self._explain(
                f'`{self.command}` was still running after {timeout:g} s.')) from None
        return self.stop()

    # -- waiting for nodes ----------------------------------------------
    def wait_for_nodes(self, names: Iterable[str], timeout: float = 20.0) -> list[str]:
        """Wait until every node in `names` is in the ROS graph; return all nodes seen.

        Names are full node names (`/sensor_publisher`, `/robot1/controller`);
        a missing leading slash is added.  If the time runs out or the command
        exits first, the command is stopped and the error says which nodes
        are missing, which ones are there, and how the output ended.
        """
        wanted = full_node_names(names)
        deadline = time.monotonic() + timeout
        while True:
            present = observer.node_names(include_hidden=True)
            missing = [name for name in wanted if name not in present]
            if not missing:
                self._wait_for_the_daemon(wanted, deadline - time.monotonic())
                return [name for name in present if not is_hidden(name)]
            if self.poll() is not None:
                self.stop()
                raise ProcessExitedError(self._explain(
                    f'`{self.command}` exited with code {self.returncode} while waiting for '
                    f'{node_list(missing)}.'))
            if time.monotonic() >= deadline:
                self.stop()
                visible = [name for name in present if not is_hidden(name)]
                raise NodesNotFoundError(self._explain(
                    f'Timed out after {timeout:g} s waiting for {node_list(missing)} from '
                    f'`{self.command}`.\nNodes in the graph: '
                    f'{", ".join(visible) if visible else "none"}.'))
            time.sleep(0.1)

    def _wait_for_the_daemon(self, nodes: list[str], timeout: float) -> None:
        """On a ROS 2 with a daemon, wait until `ros2` commands see what the observer
        saw: the nodes and the topics they use (ros2_command explains why)."""
        # `ros2 topic list` leaves hidden topics out (an action's _action/feedback)
        topics = [topic for topic, (_types, publishers, subscribers)
                  in observer.topic_endpoints(observer.observer().node).items()
                  if set(nodes) & (publishers | subscribers) and not is_hidden(topic)]
        missing = missing_from_daemon(find_ros2(), nodes, topics, timeout=max(timeout, 10.0))
        if missing:
            self.stop()
            raise NodesNotFoundError(self._explain(
                f'The ros2 daemon still does not list {", ".join(missing)} from '
                f'`{self.command}`, which the graph has; `ros2 daemon stop` and try again.'))

    def _explain(self, message: str, tail: int = 20) -> str:
        return with_output(message, self.output(last=tail))

    # -- stopping -------------------------------------------------------
    def stop(self, sigint_grace: float = SIGINT_GRACE, sigterm_grace: float = SIGTERM_GRACE,
             ) -> int:
        """Stop the command and everything it started, like Ctrl-C in a terminal.

        Sends SIGINT, then SIGTERM, then SIGKILL to the command's whole
        process group, each after a grace period; whatever the command
        started and left behind is then stopped too.  Returns the command's
        exit code; calling it again just returns the exit code.

        SIGINT goes to the whole group because that is what Ctrl-C in a
        terminal does, and what `ros2 launch` and `ros2 run` expect there: in
        Jazzy neither passes SIGINT on to its nodes when its standard input is
        a terminal (they got it from the terminal), so each node gets it once.
        """
        if not self._stopped:
            self._stopped = True
            steps = ((signal.SIGINT, sigint_grace), (signal.SIGTERM, sigterm_grace),
                     (signal.SIGKILL, None))
            for sig, grace in steps:
                if self.poll() is not None:
                    break
                _signal_group(self.pid, sig)
                try:
                    self._process.wait(timeout=grace)
                except subprocess.TimeoutExpired:
                    continue
            self._returncode = self._process.wait()
            _stop_stragglers(self.pid)
            self._reader.join(timeout=5)
            self._watchdog.terminate()
            self._watchdog.wait()
            os.close(self._terminal)
            with _running_lock:
                _running.discard(self)
        return self._returncode

    def __enter__(self) -> Background:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.stop()

    def __repr__(self) -> str:
        state = 'running' if self.running else f'exited with code {self.returncode}'
        return f'<{type(self).__name__} `{self.command}` pid {self.pid}, {state}>'


def _signal_group(pgid: int, sig: int) -> None:
    try:
        os.killpg(pgid, sig)
    except ProcessLookupError:
        pass


def _stop_stragglers(pgid: int, grace: float = 2.0) -> None:
    """Children that outlived the command (it exited first) get SIGTERM, then SIGKILL."""
    stop_group(pgid, ((signal.SIGTERM, grace), (signal.SIGKILL, grace)))


@atexit.register
def stop_all() -> None:
    """Stop every background command still running (also runs at interpreter exit)."""
    with _running_lock:
        running = list(_running)
    for background in running:
        background.stop(sigint_grace=5.0, sigterm_grace=2.0)
