"""Lesson 6.1's buffering demo: with output='screen' alone a node's print() output
waits in Python's buffer until the node ends; emulate_tty=True and
PYTHONUNBUFFERED=1 each make it arrive as it is printed.

The book sets PYTHONUNBUFFERED=1 for every run; these tests empty it, as a
student's terminal has it.  Each waits for a state (a line of output), never
for a fixed time.
"""
from __future__ import annotations

import os
import re
import signal
import subprocess
import threading
from collections.abc import Iterator
from contextlib import contextmanager

import pytest
from textbook import paths

from .._terminal import terminal_popen

HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit


class Launch:
    """`ros2 launch` in its own process group, its output collected line by line."""

    def __init__(self, launch_file: str, env: dict[str, str]) -> None:
        self.proc = terminal_popen(  # a terminal's stdin: stop() is a terminal's Ctrl+C
            ['ros2', 'launch', 'my_robot_pkg', launch_file], env=env, cwd=paths.WORKSPACE,
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            start_new_session=True)
        self.lines: list[str] = []
        self._changed = threading.Condition()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        for line in self.proc.stdout:
            with self._changed:
                self.lines.append(line.rstrip('\n'))
                self._changed.notify_all()
        with self._changed:
            self._changed.notify_all()

    def wait_for(self, pattern: str) -> list[str]:
        """The lines up to and including the first that matches ``pattern``."""
        regex = re.compile(pattern)
        with self._changed:
            found = self._changed.wait_for(
                lambda: any(regex.search(line) for line in self.lines)
                or not self._reader.is_alive(), timeout=HANG_GUARD)
            index = next((i for i, line in enumerate(self.lines) if regex.search(line)), None)
            assert found and index is not None, \
                f'no line matching {pattern!r}:\n' + '\n'.join(self.lines)
            return self.lines[:index + 1]

    def stop(self) -> list[str]:
        """Ctrl+C to the process group; every line once the launch has ended."""
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGINT)
        try:
            self.proc.wait(timeout=HANG_GUARD)
        except subprocess.TimeoutExpired:
            os.killpg(self.proc.pid, signal.SIGKILL)
            self.proc.wait()
            pytest.fail('launch did not stop on Ctrl+C:\n' + '\n'.join(self.lines))
        self._reader.join(HANG_GUARD)
        return list(self.lines)


@pytest.fixture
def terminal_env(ros_env) -> dict[str, str]:
    """The sourced environment without the book's PYTHONUNBUFFERED=1."""
    return {**ros_env, 'PYTHONUNBUFFERED': ''}


@contextmanager
def launched(launch_file: str, env: dict[str, str]) -> Iterator[Launch]:
    run = Launch(launch_file, env)
    try:
        yield run
    finally:
        run.stop()


def test_print_output_waits_in_the_buffer_until_the_node_ends(terminal_env):
    with launched('print_buffered.launch.py', terminal_env) as run:
        while_running = run.wait_for(r'\[print_counter\]: logged tick 3$')
        everything = run.stop()
    assert not [line for line in while_running if 'printed tick' in line], while_running
    after_stop = everything[len(while_running):]
    for tick in (1, 2, 3):
        assert f'[print_counter-1] print_counter printed tick {tick}' in after_stop, everything
    assert any('process has finished cleanly' in line for line in after_stop), everything


@pytest.mark.parametrize('node', ['tty_counter', 'unbuffered_counter'])
def test_emulate_tty_and_pythonunbuffered_show_print_at_once(terminal_env, node):
    with launched('print_unbuffered.launch.py', terminal_env) as run:
        # The printed line comes before the logged line of the *next* tick.
        lines = run.wait_for(rf'\[{node}\]: logged tick 2')
    printed = [line for line in lines if f'{node} printed tick 1' in line]
    assert printed and re.match(r'\[print_counter-[12]\] ', printed[0]), lines

