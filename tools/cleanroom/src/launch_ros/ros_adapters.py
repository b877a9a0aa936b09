"""An rclpy node inside the launch process, spun on a background thread.

Only lifecycle support needs it (service clients and the transition_event
subscription), so it is created on first use and shut down at the launch's
Shutdown event.
It has its own rclpy Context and installs no signal handlers: SIGINT
belongs to the LaunchService.
"""
from __future__ import annotations

import atexit
import os
import threading
import weakref
from typing import Any

from launch import LaunchContext
from launch.event_handlers import OnShutdown


class ROSAdapter:
    """Own one rclpy context, node and executor thread."""

    def __init__(self, *, argv: list[str] | None = None, autostart: bool = True) -> None:
        self.__argv = argv
        self.__ros_context: Any = None
        self.__ros_node: Any = None
        self.__executor: Any = None
        self.__thread: threading.Thread | None = None
        self.__stop = threading.Event()
        self.__workers: list[threading.Thread] = []
        if autostart:
            self.start()

    def start(self) -> None:
        # deferred: rclpy (a C extension) loads only when a launch talks to ROS
        import rclpy
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.signals import SignalHandlerOptions

        if self.__thread is not None:
            raise RuntimeError('ROSAdapter already started')
        self.__ros_context = rclpy.Context()
        # Without argv, no arguments at all: rclpy would read sys.argv, and rcl would
        # warn about the launch arguments ('Found remap rule 'foo:=bar'...'), which
        # Jazzy's launch process never does.
        rclpy.init(args=[] if self.__argv is None else self.__argv,
                   context=self.__ros_context, signal_handler_options=SignalHandlerOptions.NO)
        self.__ros_node = rclpy.create_node(f'launch_ros_{os.getpid()}',
                                            context=self.__ros_context)
        self.__executor = SingleThreadedExecutor(context=self.__ros_context)
        self.__executor.add_node(self.__ros_node)
        self.__thread = threading.Thread(target=self._spin, name='launch_ros_adapter',
                                         daemon=True)
        self.__thread.start()

    def _spin(self) -> None:
        while not self.__stop.is_set() and self.__ros_context.ok():
            try:
                self.__executor.spin_once(timeout_sec=0.1)
            except Exception:  # noqa: BLE001 - executor errors must not kill the launch
                if self.__stop.is_set() or not self.__ros_context.ok():
                    break
                raise

    @property
    def ros_context(self) -> Any:
        return self.__ros_context

    @property
    def ros_node(self) -> Any:
        return self.__ros_node

    @property
    def ros_executor(self) -> Any:
        return self.__executor

    @property
    def stopped(self) -> threading.Event:
        """Set once shutdown began; worker threads waiting on ROS should give up."""
        return self.__stop

    def start_worker(self, target: Any, name: str) -> threading.Thread:
        """Run `target` on a thread that shutdown() waits for before destroying the node.

        Workers use the node's clients, so they must end first; they watch
        `stopped` to know when.
        """
        thread = threading.Thread(target=target, name=name, daemon=True)
        self.__workers.append(thread)
        thread.start()
        return thread

    @property
    def running(self) -> bool:
        return self.__thread is not None and not self.__stop.is_set()

    def shutdown(self) -> None:
        """Stop workers and the spin thread, destroy the node, shut the context down.

        As Jazzy's, it runs at every Shutdown event of the launch, and a second
        one (two `EmitEvent(Shutdown())`, e.g. two critical processes exiting)
        raises, which the launch logs as "Caught exception in launch" and exits 1.
        """
        if not self.running:
            raise RuntimeError('Cannot shutdown a ROS adapter that is not running')
        self.__stop.set()
        for worker in self.__workers:
            worker.join(timeout=5.0)
        self.__thread.join(timeout=5.0)
        self.__executor.shutdown(timeout_sec=1.0)
        self.__ros_node.destroy_node()
        self.__ros_context.try_shutdown()


_adapters: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_lock = threading.Lock()


def get_ros_adapter(context: LaunchContext) -> ROSAdapter:
    """The adapter of this launch, started on first use and stopped at its shutdown."""
    with _lock:
        adapter = _adapters.get(context)
        if adapter is None:
            adapter = ROSAdapter()
            _adapters[context] = adapter
            context.register_event_handler(OnShutdown(
                on_shutdown=lambda _event, _context: adapter.shutdown()))
    return adapter


def get_ros_node(context: LaunchContext) -> Any:
    return get_ros_adapter(context).ros_node


def _shutdown_all() -> None:
    """Safety net for launches that ended without a Shutdown event."""
    for adapter in list(_adapters.values()):
        if adapter.running:
            adapter.shutdown()


atexit.register(_shutdown_all)
