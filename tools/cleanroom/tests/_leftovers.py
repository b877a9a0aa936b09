"""Processes a test run left behind, found by a token in their environment.

Apart from _launch_run because it must load without the clean room's launch:
the conftests use it at import, also where a real ROS 2's launch is found and
nothing here is collected.
"""
from __future__ import annotations

import os

import psutil

TOKEN_VAR = 'CLEANROOM_LAUNCH_TEST_TOKEN'


def marked_processes(token: str, var: str = TOKEN_VAR) -> list[psutil.Process]:
    """Live processes (zombies are dead already) but this one whose `var` is `token`."""
    found = []
    for proc in psutil.process_iter():
        if proc.pid == os.getpid():
            continue
        try:
            if proc.environ().get(var) == token and proc.status() != psutil.STATUS_ZOMBIE:
                found.append(proc)
        except (psutil.AccessDenied, psutil.NoSuchProcess, psutil.ZombieProcess):
            continue
    return found
