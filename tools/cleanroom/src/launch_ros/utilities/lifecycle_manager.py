"""Bridge between launch events and one lifecycle node's ROS interfaces.

- ChangeState events whose matcher picks our action are queued and sent,
  in order, to `<node>/change_state` by a worker thread that first waits
  for the service (the node may still be starting) and for our
  transition_event subscription to be matched: the node publishes each
  transition once (volatile), so a subscription that is not connected yet
  would miss the first StateTransition.
- Every message on `<node>/transition_event` becomes a StateTransition
  event, handed to the launch loop with the thread-safe emit_event_sync.
"""
from __future__ import annotations

import queue
import threading
from typing import Any

from launch import EventHandler, LaunchContext
from launch.logging import get_logger

from ..events.lifecycle import ChangeState, StateTransition
from ..ros_adapters import get_ros_adapter

_SERVICE_POLL = 0.1


class _CallbackHandler(EventHandler):
    """An EventHandler that calls a function instead of returning entities."""

    def __init__(self, event_type: type, callback: Any) -> None:
        super().__init__(matcher=lambda event: isinstance(event, event_type))
        self.__callback = callback

    def handle(self, event: Any, context: LaunchContext) -> None:
        super().handle(event, context)
        self.__callback(event, context)
        return None


class LifecycleManager:
    """Drive one LifecycleNode action through its change_state service."""

    def __init__(self, action: Any, context: LaunchContext) -> None:
        self.__action = action
        self.__context = context
        self.__requests: queue.Queue = queue.Queue()
        self.__logger = get_logger('launch_ros.actions.lifecycle_node')
        self.__client: Any = None
        self.__adapter: Any = None
        self.__connected = threading.Event()

    @property
    def node_name(self) -> str:
        return self.__action.node_name

    def start(self) -> None:
        # deferred: ROS messages and rclpy load only when a lifecycle node is managed
        import lifecycle_msgs.msg
        import lifecycle_msgs.srv

        self.__adapter = get_ros_adapter(self.__context)
        node = self.__adapter.ros_node
        name = self.node_name
        self.__client = node.create_client(lifecycle_msgs.srv.ChangeState,
                                           f'{name}/change_state')
        # deferred with the imports above
        from rclpy.event_handler import SubscriptionEventCallbacks

        node.create_subscription(
            lifecycle_msgs.msg.TransitionEvent, f'{name}/transition_event',
            self._on_transition_event, 10,
            event_callbacks=SubscriptionEventCallbacks(matched=self._on_matched))
        self.__context.register_event_handler(
            _CallbackHandler(ChangeState, self._on_change_state))
        self.__adapter.start_worker(self._work, f'lifecycle {name}')

    def _on_matched(self, info: Any) -> None:
        if info.current_count > 0:
            self.__connected.set()

    def _on_transition_event(self, msg: Any) -> None:
        # emit_event_sync is thread-safe: it wakes the launch loop from this
        # executor thread, and drops the event once the launch is over.
        self.__context.emit_event_sync(StateTransition(action=self.__action, msg=msg))

    def _on_change_state(self, event: ChangeState, context: LaunchContext) -> None:
        if event.lifecycle_node_matcher(self.__action):
            self.__requests.put(event.transition_id)

    def _work(self) -> None:
        stopped = self.__adapter.stopped
        while not stopped.is_set():
            try:
                transition_id = self.__requests.get(timeout=_SERVICE_POLL)
            except queue.Empty:
                continue
            self._request_transition(transition_id, stopped)

    def _request_transition(self, transition_id: int, stopped: threading.Event) -> None:
        # deferred: see start()
        import lifecycle_msgs.srv

        while not self.__client.wait_for_service(timeout_sec=_SERVICE_POLL):
            if stopped.is_set():
                return
        while not self.__connected.wait(_SERVICE_POLL):
            if stopped.is_set():
                return
        request = lifecycle_msgs.srv.ChangeState.Request()
        request.transition.id = transition_id
        done = threading.Event()
        future = self.__client.call_async(request)
        future.add_done_callback(lambda _: done.set())
        while not done.wait(_SERVICE_POLL):
            if stopped.is_set():
                return
        response = future.result()
        if response is None or not response.success:
            label = ChangeState.valid_transitions.get(transition_id, transition_id)
            self.__logger.error(
                f"Failed to make transition '{label}' for LifecycleNode '{self.node_name}'")
