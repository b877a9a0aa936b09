"""A LifecycleNode's launch keeps its launch arguments away from rcl.

The launch process's own ROS node (made for the lifecycle services) is
initialised without arguments on Jazzy: `ros2 launch file foo:=bar` prints
no "[rcl]: Found remap rule 'foo:=bar'. This syntax is deprecated." warning.
Expected output recorded from Jazzy (launch_ros 0.26.6) with this launch file.
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

from launch_ros.ros_adapters import ROSAdapter

ROS2 = str(Path(sys.executable).parent / 'ros2')
LAUNCH_FILE = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, TimerAction
from launch.events import Shutdown
from launch_ros.actions import LifecycleNode


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('foo', default_value='x'),
        LifecycleNode(executable='python3', arguments=['-c', 'import time; time.sleep(10)'],
                      name='lc_node', namespace='', output='screen'),
        TimerAction(period=3.0, actions=[EmitEvent(event=Shutdown(reason='done'))]),
    ])
"""
# Jazzy's screen, the log folder and pids left out
EXPECTED = [
    '[INFO] [launch]: Default logging verbosity is set to INFO',
    '[INFO] [python3-1]: process started with pid [PID]',
    "[INFO] [python3-1]: sending signal 'SIGINT' to process[python3-1]",
    '[python3-1] Traceback (most recent call last):',
    '[python3-1]   File "<string>", line 1, in <module>',
    '[python3-1] KeyboardInterrupt',
    "[ERROR] [python3-1]: process has died [pid PID, exit code -2, cmd 'python3 -c import "
    "time; time.sleep(10) --ros-args -r __node:=lc_node -r __ns:=/'].",
]


def test_launch_arguments_do_not_reach_rcl(tmp_path):
    path = tmp_path / 'lc.launch.py'
    path.write_text(textwrap.dedent(LAUNCH_FILE))
    env = dict(os.environ, RCUTILS_COLORIZED_OUTPUT='0', PYTHONWARNINGS='ignore')
    result = subprocess.run([ROS2, 'launch', str(path), 'foo:=bar'], env=env, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            stdin=subprocess.DEVNULL, timeout=60)
    lines = [re.sub(r'(pid \[?)\d+', r'\1PID', line) for line in result.stdout.splitlines()
             if not line.startswith('[INFO] [launch]: All log files can be found below')]
    assert result.returncode == 0
    assert lines == EXPECTED


def test_adapter_without_argv_ignores_sys_argv(monkeypatch, capfd):
    monkeypatch.setattr(sys, 'argv', ['launch', 'foo:=bar'])
    adapter = ROSAdapter()
    try:
        assert adapter.ros_node.get_name() == f'launch_ros_{os.getpid()}'
    finally:
        adapter.shutdown()
    assert 'Found remap rule' not in ''.join(capfd.readouterr())
