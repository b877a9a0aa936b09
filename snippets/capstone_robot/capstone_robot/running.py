"""Run one node until Ctrl+C or the launch stops it: the same ``main`` for every node."""
from __future__ import annotations

from collections.abc import Callable

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


class ConfigurationError(ValueError):
    """A parameter value the node cannot work with: logged plainly, exit code 1."""


class Finished(Exception):
    """Raised from a callback when the node cannot go on (it has logged why);
    the process ends with exit code `code`, which a launch's OnProcessExit sees."""

    def __init__(self, code: int = 1) -> None:
        super().__init__(code)
        self.code = code


def run(make_node: Callable[[], Node], args: list[str] | None = None) -> int:
    """Spin the node ``make_node`` builds; 0 when stopped on purpose (Ctrl+C, launch).

    A launch may stop a node at any moment, also while it is still starting (a
    fault test that kills a critical node early, on a busy machine).  Then
    rclpy's Ctrl+C handler has already shut the context down and creating the
    next publisher or timer fails; that is a stop on purpose too, not a crash.
    """
    node = None
    initialised = False
    try:
        rclpy.init(args=args)
        initialised = True
        node = make_node()  # Ctrl+C may come while it starts: it is on the graph already
        rclpy.spin(node)
    except ConfigurationError as error:
        rclpy.logging.get_logger('capstone_robot').fatal(str(error))
        return 1
    except Finished as finished:
        return finished.code
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    except Exception:
        if not initialised or rclpy.ok():
            raise  # a real error, not a stop while starting
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
