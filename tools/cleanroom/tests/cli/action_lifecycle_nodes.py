"""Nodes for the `ros2 action|lifecycle` tests: lifecycle nodes, and an action server.

Run as `python action_lifecycle_nodes.py lifecycle|action` (the tests use
`started()`); prints `ready NAME` once up and spins until SIGINT/SIGTERM.  The
action server needs turtlesim's RotateAbsolute (the one action type a ROS 2
sourced with turtlesim, or the book's workspace, offers): it answers feedback
`remaining: 1.0`, then a result of half the goal, and rejects negative goals.
"""
from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
from collections.abc import Iterator

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.lifecycle import Node as LifecycleNode
from rclpy.lifecycle import TransitionCallbackReturn
from rclpy.node import Node


class Refusing(LifecycleNode):
    """Configures, but refuses to activate: `Transitioning failed`."""

    def on_activate(self, state: object) -> TransitionCallbackReturn:
        return TransitionCallbackReturn.FAILURE


def lifecycle() -> list[Node]:
    return [LifecycleNode('lc_node'), Refusing('lc_refusing', namespace='/ns'),
            LifecycleNode('_hidden_lc')]


def action() -> list[Node]:
    from rclpy.action import ActionClient, ActionServer, GoalResponse
    from turtlesim.action import RotateAbsolute

    def execute(goal_handle: object) -> object:
        goal_handle.publish_feedback(RotateAbsolute.Feedback(remaining=1.0))
        goal_handle.succeed()
        return RotateAbsolute.Result(delta=goal_handle.request.theta / 2)

    server = Node('action_server')
    server.server = ActionServer(
        server, RotateAbsolute, 'rotate', execute_callback=execute,
        goal_callback=lambda goal: GoalResponse.REJECT if goal.theta < 0 else GoalResponse.ACCEPT)
    client = Node('action_client')
    client.client = ActionClient(client, RotateAbsolute, 'rotate')
    return [server, client]


KINDS = {'lifecycle': lifecycle, 'action': action}


def main() -> None:
    rclpy.init(args=sys.argv)
    signal.signal(signal.SIGTERM, lambda *_: rclpy.try_shutdown())
    nodes = KINDS[sys.argv[1]]()
    executor = SingleThreadedExecutor()
    for node in nodes:
        executor.add_node(node)
    print('ready', nodes[0].get_fully_qualified_name(), flush=True)
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        for node in nodes:
            node.destroy_node()
        rclpy.try_shutdown()


@contextlib.contextmanager
def started(kind: str, env: dict[str, str]) -> Iterator[subprocess.Popen]:
    """Run the `kind` nodes in their own session until the block ends (SIGINT, then
    SIGKILL if they linger; always reaped)."""
    proc = subprocess.Popen([sys.executable, __file__, kind], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True, start_new_session=True)
    try:
        assert proc.stdout.readline().startswith('ready '), f'{kind} nodes did not start'
        yield proc
    finally:
        for sig in (signal.SIGINT, signal.SIGKILL):
            if proc.poll() is None:
                os.killpg(proc.pid, sig)
                with contextlib.suppress(subprocess.TimeoutExpired):
                    proc.wait(timeout=5)
        proc.wait()


if __name__ == '__main__':
    main()
