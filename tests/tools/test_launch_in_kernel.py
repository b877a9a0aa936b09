"""A launch run inside a notebook kernel must not outlive an interrupt.

Instructors press "interrupt" on a cell that is running a launch; the
launch's processes must all stop and the kernel must stay usable.  Uses
only the public launch API, so it holds for a real ROS 2 install too.
"""
from __future__ import annotations

import textwrap

import psutil
import pytest
from jupyter_client.manager import start_new_kernel

from .._polling import wait_for

# A child that, like a well-behaved node, ends cleanly on SIGINT.
SLEEPER = ('import signal, sys, time; '
           'signal.signal(signal.SIGINT, lambda *a: sys.exit(0)); time.sleep(300)')

LAUNCH_CELL = textwrap.dedent("""
    import sys
    from launch import LaunchDescription, LaunchService
    from launch.actions import ExecuteProcess
    from launch_ros.actions import Node

    SLEEPER = %r
    description = LaunchDescription([
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
        ExecuteProcess(cmd=[sys.executable, '-c', SLEEPER], name='sleeper', output='screen'),
    ])
    service = LaunchService()
    service.include_launch_description(description)
    # A kernel already runs an asyncio loop, so a notebook awaits the launch
    # instead of calling service.run() (which would start a second loop).
    print('launch returned', await service.run_async())
""") % SLEEPER


def _children(pid: int) -> list[psutil.Process]:
    try:
        return psutil.Process(pid).children(recursive=True)
    except psutil.NoSuchProcess:
        return []



@pytest.fixture
def kernel(ros_env, tmp_path):
    km, kc = start_new_kernel(kernel_name='python3', env=ros_env, cwd=str(tmp_path))
    try:
        yield km, kc
    finally:
        kc.stop_channels()
        km.shutdown_kernel(now=True)


def _cell_output(kc, msg_id: str, until: str | None = None) -> str:
    """What the cell printed, up to `until` appearing or the kernel going idle."""
    texts = []
    while True:
        if until is not None and until in ''.join(texts):
            return ''.join(texts)
        msg = kc.get_iopub_msg(timeout=60)
        if msg['parent_header'].get('msg_id') != msg_id:
            continue
        if msg['msg_type'] == 'stream':
            texts.append(msg['content']['text'])
        elif msg['msg_type'] == 'error':
            texts.append('\n'.join(msg['content']['traceback']))
        elif msg['msg_type'] == 'status' and msg['content']['execution_state'] == 'idle':
            return ''.join(texts)


def _launched(kernel_pid: int) -> list[psutil.Process]:
    """The launch's processes: the sensor node and the sleeper, once both run."""
    procs = _children(kernel_pid)
    cmdlines = [' '.join(p.cmdline()) for p in procs if p.is_running()]
    started = any('sensor_publisher' in c for c in cmdlines) and any(
        'signal.SIGINT' in c for c in cmdlines)
    return procs if started else []


def test_interrupting_the_kernel_stops_every_launched_process(kernel):
    km, kc = kernel
    kernel_pid = km.provisioner.process.pid
    msg_id = kc.execute(LAUNCH_CELL)
    # Interrupt only once the node is up and publishing: a process interrupted
    # while still starting dies of the signal under Jazzy as well.
    early = _cell_output(kc, msg_id, until='Reading #1')
    launched = wait_for(lambda: _launched(kernel_pid), 30, 'both launched processes')

    km.interrupt_kernel()
    reply = kc.get_shell_msg(timeout=60)
    assert reply['parent_header']['msg_id'] == msg_id
    output = early + _cell_output(kc, msg_id)

    gone, alive = psutil.wait_procs(launched, timeout=30)
    assert not alive, 'still running after the interrupt: %s' % [
        ' '.join(p.cmdline()) for p in alive]
    # An interrupt is a Ctrl-C: every process gets one SIGINT and ends cleanly.
    assert 'process has died' not in output, output
    assert output.count('process has finished cleanly') == 2, output
    assert 'launch returned 0' in output, output

    # The kernel survived the interrupt and runs the next cell.
    kc.execute_interactive('x = 6 * 7', timeout=30)
    check = kc.execute_interactive('assert x == 42', timeout=30)
    assert check['content']['status'] == 'ok'
