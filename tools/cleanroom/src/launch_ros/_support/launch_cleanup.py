"""Release what launch_ros made for one launch when that launch shuts down.

Temporary parameter files and the in-process ROS node (lifecycle support)
belong to one LaunchContext; an OnShutdown handler, registered the first
time it is needed, removes them.  `param_files` also has an atexit hook for
launches that die without a Shutdown event.
"""
from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import Any

from launch import LaunchContext
from launch.event_handlers import OnShutdown

from .param_files import remove_temporary_files

_registered: weakref.WeakSet = weakref.WeakSet()
_callbacks: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def owner_key(context: LaunchContext) -> int:
    """The key temporary files of this launch are filed under."""
    return id(context)


def add_shutdown_callback(context: LaunchContext, callback: Callable[[], None]) -> None:
    """Run `callback()` when this launch shuts down (after the files are removed)."""
    ensure_cleanup_registered(context)
    _callbacks.setdefault(context, []).append(callback)


def run_cleanup(context: LaunchContext) -> None:
    """Remove this launch's temporary files and run its shutdown callbacks, once."""
    remove_temporary_files(owner_key(context))
    callbacks = _callbacks.pop(context, [])
    for callback in callbacks:
        callback()


def ensure_cleanup_registered(context: LaunchContext) -> None:
    if context in _registered:
        return

    def on_shutdown(event: Any, shutdown_context: LaunchContext) -> None:
        run_cleanup(context)

    context.register_event_handler(OnShutdown(on_shutdown=on_shutdown))
    _registered.add(context)
