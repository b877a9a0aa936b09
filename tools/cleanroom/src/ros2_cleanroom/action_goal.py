"""Send one goal to an action server and follow it to its result, as `ros2 action
send_goal` prints it.

Each message is printed as YAML after a header whose indent only the first
line gets (Jazzy's layout).  In Jazzy, Ctrl-C (or SIGTERM) lets rclpy shut
the command's context down first: waiting for the server then fails with
rcl's error, and a running goal's cancel request never goes out, which the
command reports as a failure.  The context here is private (rclpy installs
no signal handlers for it), so an interrupt shuts it down itself.
"""
from __future__ import annotations

import signal
from typing import Any

from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.executors import SingleThreadedExecutor
from rclpy.task import Future

from ros2_cleanroom import cli_node
from ros2_cleanroom.interfaces import message_to_yaml
from ros2_cleanroom.verb_args import fail

#: GoalStatus values by number: `STATUS_SUCCEEDED` -> `SUCCEEDED`.
STATUS_NAMES = {value: name.removeprefix('STATUS_') for name, value in vars(GoalStatus).items()
                if name.startswith('STATUS_') and isinstance(value, int)}


def _spin_until(executor: SingleThreadedExecutor, future: Future) -> None:
    while not future.done():
        executor.spin_once(timeout_sec=0.1)


def _interrupt(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt


def send_goal(action_name: str, action_type: type, type_name: str, goal: Any,
              feedback: bool) -> int:
    """Wait for the server (as long as it takes), send `goal`, print what comes back."""
    # even when started in the background by a shell that ignores SIGINT
    signal.signal(signal.SIGINT, _interrupt)
    signal.signal(signal.SIGTERM, _interrupt)
    node_prefix = '_ros2cli_send_goal_' + type_name.replace('/', '_')
    with cli_node.cli_node(node_prefix) as node:
        client = ActionClient(node, action_type, action_name)
        executor = SingleThreadedExecutor(context=node.context)
        executor.add_node(node)
        print('Waiting for an action server to become available...', flush=True)
        try:
            while not client.wait_for_server(timeout_sec=1.0):
                pass
        except KeyboardInterrupt:
            node.context.try_shutdown()
            try:
                client.server_is_ready()  # rcl's words for a context shut down
            except Exception as error:  # noqa: BLE001 - reported as Jazzy does
                return fail(str(error))
            return 1
        print('Sending goal:\n     ' + message_to_yaml(goal), flush=True)
        callback = _print_feedback if feedback else None
        accepted = client.send_goal_async(goal, feedback_callback=callback)
        _spin_until(executor, accepted)
        handle = accepted.result()
        if handle is None or not handle.accepted:
            print('Goal was rejected.')
            return 0
        print(f'Goal accepted with ID: {bytes(handle.goal_id.uuid).hex()}\n', flush=True)
        try:
            result = handle.get_result_async()
            _spin_until(executor, result)
        except KeyboardInterrupt:
            return _cancel(executor, handle)
        response = result.result()
        print('Result:\n    ' + message_to_yaml(response.result))
        print(f'Goal finished with status: {STATUS_NAMES.get(response.status, "UNKNOWN")}')
        return 0


def _print_feedback(message: Any) -> None:
    print('Feedback:\n    ' + message_to_yaml(message.feedback), flush=True)


def _cancel(executor: SingleThreadedExecutor, handle: Any) -> int:
    """Jazzy's cancel request after Ctrl-C: its context is shut down, so the request
    gets no answer and no exception, and the command fails printing that (None)."""
    print('Canceling goal...', flush=True)
    executor.context.try_shutdown()
    return fail('Exception while canceling goal: None')
