"""tools/ddsfix: the shim that keeps the wheels' Fast DDS from hanging a node at shutdown.

The wheels' libstdc++ turns a "wait forever" into a negative timespec, and
glibc's pthread_cond_timedwait answers EINVAL at once without releasing the
mutex, so the caller spins holding it (tools/ddsfix/forever_wait.c).  These
tests call pthread_cond_timedwait with such a deadline in a child process, with
and without the shim, and check that every ROS run of the book gets the shim.
"""
from __future__ import annotations

import errno
import json
import subprocess
import sys
from pathlib import Path

import pytest
from textbook import isolation

#: The wheels put Fast DDS into the venv; a real ROS 2 (no shim built) does not.
WHEELS = (Path(sys.prefix) / 'lib' / 'libfastrtps.so').exists()
needs_wheels = pytest.mark.skipif(not WHEELS, reason='Fast DDS is not the PyPI wheels here')

#: Waits on a condition variable that another thread signals 1 s later, with the
#: deadline argv[1] ('overflowed': what the wheel makes of steady_clock's max(),
#: 'soon': a real one 0.1 s ahead); prints the return code, the seconds it took and
#: whether the signal had come.
_CHILD = """
import ctypes, json, sys, threading, time

class timespec(ctypes.Structure):
    _fields_ = [('tv_sec', ctypes.c_long), ('tv_nsec', ctypes.c_long)]

libc = ctypes.CDLL(None)
mutex = ctypes.create_string_buffer(64)  # all zero: PTHREAD_MUTEX_INITIALIZER
cond = ctypes.create_string_buffer(64)   # all zero: PTHREAD_COND_INITIALIZER
signalled = []

def signal():
    time.sleep(1.0)
    libc.pthread_mutex_lock(mutex)
    signalled.append(True)
    libc.pthread_cond_signal(cond)
    libc.pthread_mutex_unlock(mutex)

if sys.argv[1] == 'overflowed':
    deadline = timespec(-7427607324, -568803076)
else:
    now = time.clock_gettime(time.CLOCK_REALTIME) + 0.1
    deadline = timespec(int(now), int(now % 1 * 1e9))
libc.pthread_mutex_lock(mutex)
threading.Thread(target=signal, daemon=True).start()
start = time.monotonic()
code = libc.pthread_cond_timedwait(cond, mutex, ctypes.byref(deadline))
while code == 0 and not signalled:  # a spurious wake-up: wait again
    code = libc.pthread_cond_timedwait(cond, mutex, ctypes.byref(deadline))
took = time.monotonic() - start
print(json.dumps([code, took, bool(signalled)]))
libc.pthread_mutex_unlock(mutex)
"""


def _wait(deadline: str, preload: str | None) -> tuple[int, float, bool]:
    env = {'PATH': '/usr/bin:/bin', **({'LD_PRELOAD': preload} if preload else {})}
    done = subprocess.run([sys.executable, '-c', _CHILD, deadline], env=env, capture_output=True,
                          text=True, timeout=30, check=True)
    code, took, signalled = json.loads(done.stdout)
    return code, took, signalled


@needs_wheels
def test_every_ros_run_of_the_book_gets_the_shim():
    assert isolation.DDSFIX.is_file(), f'{isolation.DDSFIX} was not built: make setup'
    with isolation.acquire_domain() as lease:
        alone = lease.env(base={})
        kept = lease.apply({'LD_PRELOAD': '/other/libpreloaded.so'})
    assert alone['LD_PRELOAD'] == str(isolation.DDSFIX)
    assert kept['LD_PRELOAD'].split() == ['/other/libpreloaded.so', str(isolation.DDSFIX)]


def test_no_shim_is_preloaded_where_none_was_built(monkeypatch, tmp_path):
    """A real ROS 2 (the parity run's Jazzy, a student's Ubuntu) needs none: nothing is
    preloaded, and a shim path inherited from the wheels' environment is dropped."""
    inherited = str(isolation.DDSFIX)
    monkeypatch.setattr(isolation, 'DDSFIX', tmp_path / 'lib' / 'ddsfix' / isolation.DDSFIX.name)
    with isolation.acquire_domain() as lease:
        assert 'LD_PRELOAD' not in lease.apply({'LD_PRELOAD': inherited})
        assert lease.apply({'LD_PRELOAD': f'/a.so {inherited}'})['LD_PRELOAD'] == '/a.so'


def test_without_the_shim_an_overflowed_deadline_fails_at_once():
    """The bug, as glibc has it: EINVAL before the signal, the mutex never let go."""
    code, took, signalled = _wait('overflowed', preload=None)
    assert code == errno.EINVAL and not signalled, (code, took, signalled)


@needs_wheels
def test_the_shim_turns_an_overflowed_deadline_into_a_real_wait():
    code, took, signalled = _wait('overflowed', preload=str(isolation.DDSFIX))
    assert code == 0 and signalled, (code, took, signalled)


@needs_wheels
def test_the_shim_leaves_a_real_deadline_alone():
    code, took, signalled = _wait('soon', preload=str(isolation.DDSFIX))
    assert code == errno.ETIMEDOUT and not signalled, (code, took, signalled)
