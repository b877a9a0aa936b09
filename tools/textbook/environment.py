"""The environment every ROS run gets: project tools on PATH, a private
domain, localhost-only discovery and the snippets workspace sourced."""
from __future__ import annotations

import os

from . import paths, workspace
from .isolation import DomainLease


def ros_env(lease: DomainLease, base: dict[str, str] | None = None,
            source_workspace: bool = True) -> dict[str, str]:
    """Environment for a lesson kernel, a node or a test in ``lease``'s domain."""
    env = dict(os.environ if base is None else base)
    env['PATH'] = paths.tool_path(env.get('PATH', ''))
    env['PYTHONUNBUFFERED'] = '1'  # output of nodes appears as it happens, as in a terminal
    env['NO_MKDOCS_2_WARNING'] = '1'
    # A student's shell does not set this, and it changes what colcon prints
    # (setuptools then warns that byte-compiling is disabled).
    env.pop('PYTHONDONTWRITEBYTECODE', None)
    env = lease.apply(env)
    if source_workspace:
        env = workspace.sourced_env(env, workspace.ensure_built())
    return env
