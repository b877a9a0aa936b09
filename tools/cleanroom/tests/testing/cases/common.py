"""Process actions shared by the launch test cases."""
import os
import sys

from launch.actions import ExecuteProcess

PROC = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'proc.py')


def proc(name, *args, **kwargs):
    """An ExecuteProcess running proc.py with `args`."""
    return ExecuteProcess(cmd=[sys.executable, PROC, *args], name=name, **kwargs)
