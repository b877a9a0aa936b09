"""Start one OS process and watch it from the asyncio loop.

Output pipes (or pseudo-terminals with emulate_tty) are read with
`loop.add_reader`, and the exit is noticed through a pidfd (Linux >= 5.3),
falling back to a waiting thread.  This keeps the loop free of child-watcher
threads per process and makes every start cheap.

Every child gets PR_SET_PDEATHSIG=SIGKILL (rclhelpers.processes) so that it
dies with the launch even when the launch itself is killed or crashes.  It is
set in the child between fork and exec (preexec_fn), followed by a check that
the parent is still the launch: a launch killed just before the prctl would
otherwise leave the child behind.  (`setpriv --pdeathsig` starts processes faster but
has exactly that window, which a busy machine hits.)
"""
from __future__ import annotations

import asyncio
import os
import pty
import signal
import subprocess
import threading
from collections.abc import Callable

from rclhelpers.processes import die_with_parent

_EXIT_GRACE_SECONDS = 0.5  # how long to wait for pipes held open by grandchildren


class RunningProcess:
    """One child process whose output and exit are reported through callbacks.

    `on_output(fd, data)` gets raw chunks (fd 1 or 2); `on_exit(returncode)`
    is called once, after the remaining output has been delivered.
    """

    def __init__(self, loop: asyncio.AbstractEventLoop, cmd: list[str], *,
                 cwd: str | None, env: dict[str, str], shell: bool, emulate_tty: bool,
                 on_output: Callable[[int, bytes], None],
                 on_exit: Callable[[int], None]) -> None:
        self._loop = loop
        self._cmd = cmd
        self._cwd = cwd
        self._env = env
        self._shell = shell
        self._emulate_tty = emulate_tty
        self._on_output = on_output
        self._on_exit = on_exit
        self._popen: subprocess.Popen | None = None
        self._readers: dict[int, int] = {}  # our fd -> child's fd number (1 or 2)
        self._pidfd: int | None = None
        self._returncode: int | None = None
        self._finished = False
        self._grace: asyncio.TimerHandle | None = None
        self._spawned_fds: list[int] = []

    @property
    def pid(self) -> int:
        """The child's pid."""
        assert self._popen is not None
        return self._popen.pid

    @property
    def returncode(self) -> int | None:
        """The exit code once the child has exited."""
        return self._returncode

    @property
    def running(self) -> bool:
        """True until the child has exited."""
        return self._popen is not None and self._returncode is None

    def start(self) -> None:
        """Spawn and attach in one go (on the loop's thread)."""
        self.spawn()
        self.attach()

    def spawn(self) -> None:
        """Fork and exec the child; raises OSError if it cannot be started.

        Safe to call from a worker thread (the launch's spawner threads, which
        live as long as the launch: the death signal follows the thread that
        started the child).  Call attach() on the loop's thread afterwards.
        """
        parents: list[int] = []
        children: list[int] = []
        for _ in (1, 2):
            if self._emulate_tty:
                parent_fd, child_fd = pty.openpty()
            else:
                parent_fd, child_fd = os.pipe()
            parents.append(parent_fd)
            children.append(child_fd)
        me = os.getpid()
        args = ['/bin/sh', '-c', ' '.join(self._cmd)] if self._shell else list(self._cmd)
        try:
            self._popen = subprocess.Popen(
                args, cwd=self._cwd, env=self._env,
                stdin=subprocess.PIPE, stdout=children[0], stderr=children[1],
                preexec_fn=lambda: die_with_parent(me, signal.SIGKILL), close_fds=True)
        except BaseException:
            for fd in parents:
                os.close(fd)
            raise
        finally:
            for fd in children:
                os.close(fd)
        self._spawned_fds = parents

    def attach(self) -> None:
        """Start reading the child's output and watching its exit (loop's thread)."""
        for number, fd in zip((1, 2), self._spawned_fds, strict=True):
            os.set_blocking(fd, False)
            self._readers[fd] = number
            self._loop.add_reader(fd, self._read, fd)
        self._spawned_fds = []
        self._watch_exit()

    def _watch_exit(self) -> None:
        try:
            self._pidfd = os.pidfd_open(self.pid)
        except (AttributeError, OSError):
            threading.Thread(target=self._wait_in_thread, daemon=True,
                             name=f'wait-{self.pid}').start()
            return
        self._loop.add_reader(self._pidfd, self._reap)

    def _wait_in_thread(self) -> None:
        assert self._popen is not None
        self._popen.wait()
        try:
            self._loop.call_soon_threadsafe(self._reap)
        except RuntimeError:  # loop already closed
            pass

    def _reap(self) -> None:
        assert self._popen is not None
        returncode = self._popen.poll()
        if returncode is None:
            return
        if self._pidfd is not None:
            self._loop.remove_reader(self._pidfd)
            os.close(self._pidfd)
            self._pidfd = None
        self._returncode = returncode
        self._close_stdin()
        if self._readers:
            self._grace = self._loop.call_later(_EXIT_GRACE_SECONDS, self._finish)
        else:
            self._finish()

    def _read(self, fd: int) -> None:
        try:
            data = os.read(fd, 65536)
        except BlockingIOError:
            return
        except OSError:  # EIO: the pty's other side is closed
            data = b''
        if data:
            self._on_output(self._readers[fd], data)
            return
        self._close_reader(fd)
        if not self._readers and self._returncode is not None:
            self._finish()

    def _close_reader(self, fd: int) -> None:
        self._loop.remove_reader(fd)
        os.close(fd)
        del self._readers[fd]

    def _close_stdin(self) -> None:
        if self._popen is not None and self._popen.stdin is not None:
            try:
                self._popen.stdin.close()
            except OSError:
                pass

    def _finish(self) -> None:
        if self._finished:
            return
        self._finished = True
        if self._grace is not None:
            self._grace.cancel()
        for fd in list(self._readers):
            self._close_reader(fd)
        assert self._returncode is not None
        self._on_exit(self._returncode)

    def send_signal(self, signum: int) -> None:
        """Send a signal unless the child has already exited."""
        if self.running:
            try:
                os.kill(self.pid, signum)
            except ProcessLookupError:
                pass
