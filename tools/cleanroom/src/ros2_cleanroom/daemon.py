"""The ROS 2 daemon: a background process whose node keeps watching the graph.

As in Jazzy's ros2cli, the first introspection command (`ros2 node list`,
`ros2 topic info`, ...) that finds no daemon starts one and discovers the
graph itself; later commands ask the daemon, which answers at once with
what it has seen so far (a node started a moment ago may not be in it yet).
`ros2 daemon start|stop|status` manage it; `--no-daemon` neither starts nor
uses it.  One daemon per ROS_DOMAIN_ID, reached on localhost at port
11511 + domain id; its command line carries `--name ros2-daemon`, as
Jazzy's does, so process tools recognise it.

Requests are (method, arguments) of the graph methods of rclpy's Node that
the verbs use; the answers are plain data (topic endpoint infos and their
QoS profiles are rebuilt on the caller's side).
"""
from __future__ import annotations

import argparse
import contextlib
import os
import subprocess
import sys
import time
import uuid
from multiprocessing import AuthenticationError
from multiprocessing.connection import Client, Connection, Listener
from typing import Any

PORT_BASE = 11511
#: Seconds a daemon nobody asks anything keeps running (Jazzy: two hours).
IDLE_TIMEOUT = 2 * 60 * 60
#: Seconds a request may take to arrive once a caller connected.
REQUEST_TIMEOUT = 5.0
#: Seconds `ros2 daemon start` waits for a new daemon to answer.
START_TIMEOUT = 10.0
CONNECT_TIMEOUT = 2.0
#: Seconds the command that started a daemon waits for it to see what it saw.
HANDOVER_TIMEOUT = 5.0
#: The Node methods a daemon answers (everything else is refused).
GRAPH_METHODS = frozenset({
    'get_node_names_and_namespaces', 'get_topic_names_and_types',
    'get_publisher_names_and_types_by_node', 'get_subscriber_names_and_types_by_node',
    'get_service_names_and_types_by_node', 'get_client_names_and_types_by_node',
    'get_service_names_and_types', 'get_publishers_info_by_topic',
    'get_subscriptions_info_by_topic', 'count_publishers', 'count_subscribers',
    'get_action_server_names_and_types_by_node', 'get_action_client_names_and_types_by_node'})
#: Graph queries rclpy offers as functions of a node rather than as its methods.
_ACTION_METHODS = {'get_action_server_names_and_types_by_node',
                   'get_action_client_names_and_types_by_node'}
_ENDPOINT_METHODS = {'get_publishers_info_by_topic', 'get_subscriptions_info_by_topic'}


def domain_id() -> int:
    try:
        return int(os.environ.get('ROS_DOMAIN_ID') or 0)
    except ValueError:
        return 0


def _address() -> tuple[str, int]:
    return 'localhost', PORT_BASE + domain_id()


def _authkey() -> bytes:
    return f'ros2-daemon-{os.getuid()}-{domain_id()}'.encode()


def _request(method: str, *args: Any, timeout: float = CONNECT_TIMEOUT) -> Any:
    """One request to the running daemon; OSError/EOFError when there is none."""
    connection = _connect(timeout)
    with contextlib.closing(connection):
        connection.send((method, args))
        ok, answer = connection.recv()
    if not ok:
        raise RuntimeError(answer)
    return answer


def _connect(timeout: float) -> Connection:
    deadline = time.monotonic() + timeout
    while True:
        try:
            return Client(_address(), authkey=_authkey())
        except (ConnectionRefusedError, FileNotFoundError):
            raise
        except OSError:
            if time.monotonic() >= deadline:
                raise
            time.sleep(0.05)


def is_running() -> bool:
    try:
        return _request('ping') == 'pong'
    except (OSError, EOFError, RuntimeError):
        return False


def spawn() -> None:
    """Start a daemon in the background (it outlives this command)."""
    subprocess.Popen(
        [sys.executable, '-c', 'from ros2_cleanroom.daemon import main; main()',
         '--name', 'ros2-daemon', '--ros-domain-id', str(domain_id())],
        stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        start_new_session=True, close_fds=True)


def start() -> bool:
    """Start a daemon and wait until it answers; False if it never did."""
    spawn()
    deadline = time.monotonic() + START_TIMEOUT
    while time.monotonic() < deadline:
        if is_running():
            return True
        time.sleep(0.1)
    return False


def wait_until_seen(nodes: list[str], timeout: float = HANDOVER_TIMEOUT) -> None:
    """Wait (a bounded while) until a new daemon answers and lists `nodes`, which the
    command that started it has seen: the next command then sees them too."""
    from rclhelpers.names import full_name
    deadline = time.monotonic() + timeout
    wanted = set(nodes)
    while time.monotonic() < deadline:
        try:
            seen = {full_name(n, ns) for n, ns in _request('get_node_names_and_namespaces')}
        except (OSError, EOFError, RuntimeError):
            seen = set()
        if wanted <= seen:
            return
        time.sleep(0.1)


def stop() -> bool:
    """Ask the running daemon to exit; False if none was running."""
    try:
        _request('shutdown')
    except (OSError, EOFError, RuntimeError):
        return False
    return True


class DaemonGraph:
    """The daemon's view of the graph, with the graph methods of rclpy's Node.

    It is no node of the command's own: every endpoint counts, the daemon's too
    (Jazzy's `ros2 topic info /rosout` counts the daemon's publisher).
    """

    def get_name(self) -> str:
        return ''

    def get_namespace(self) -> str:
        return ''

    def __getattr__(self, method: str) -> Any:
        if method not in GRAPH_METHODS:
            raise AttributeError(method)

        def call(*args: Any) -> Any:
            answer = _request(method, *args)
            if method in _ENDPOINT_METHODS:
                return [_endpoint_info(info) for info in answer]
            if method.endswith('names_and_types') or method.endswith('_by_node') \
                    or method == 'get_node_names_and_namespaces':
                return [tuple(item) for item in answer]
            return answer
        return call


def _plain_endpoint(info: Any) -> dict[str, Any]:
    qos = info.qos_profile
    return {'node_name': info.node_name, 'node_namespace': info.node_namespace,
            'topic_type': info.topic_type, 'endpoint_type': int(info.endpoint_type),
            'topic_type_hash': (info.topic_type_hash.version, info.topic_type_hash.value),
            'endpoint_gid': list(info.endpoint_gid),
            'qos_profile': {
                'history': int(qos.history), 'depth': qos.depth,
                'reliability': int(qos.reliability), 'durability': int(qos.durability),
                'liveliness': int(qos.liveliness),
                'deadline': qos.deadline.nanoseconds, 'lifespan': qos.lifespan.nanoseconds,
                'liveliness_lease_duration': qos.liveliness_lease_duration.nanoseconds,
                'avoid_ros_namespace_conventions': qos.avoid_ros_namespace_conventions}}


def _endpoint_info(plain: dict[str, Any]) -> Any:
    from rclpy.duration import Duration
    from rclpy.qos import QoSProfile
    from rclpy.topic_endpoint_info import TopicEndpointInfo, TopicEndpointTypeEnum
    from rclpy.type_hash import TypeHash
    qos = dict(plain['qos_profile'])
    version, value = plain['topic_type_hash']
    for name in ('deadline', 'lifespan', 'liveliness_lease_duration'):
        qos[name] = Duration(nanoseconds=qos[name])
    return TopicEndpointInfo(
        node_name=plain['node_name'], node_namespace=plain['node_namespace'],
        topic_type=plain['topic_type'], topic_type_hash=TypeHash(version, value),
        endpoint_type=TopicEndpointTypeEnum(plain['endpoint_type']),
        endpoint_gid=plain['endpoint_gid'], qos_profile=QoSProfile(**qos))


def _answer(node: Any, method: str, args: tuple) -> Any:
    if method in _ACTION_METHODS:
        from rclpy.action import graph
        return getattr(graph, method)(node, *args)
    result = getattr(node, method)(*args)
    if method in _ENDPOINT_METHODS:
        return [_plain_endpoint(info) for info in result]
    return result


def serve(listener: Listener, node: Any) -> None:
    """Answer requests until one says shutdown or nobody asked for IDLE_TIMEOUT."""
    last = time.monotonic()
    listener._listener._socket.settimeout(1.0)  # wake up to check the idle time
    while time.monotonic() - last < IDLE_TIMEOUT:
        try:
            connection = listener.accept()
        except TimeoutError:
            continue
        except (OSError, EOFError, AuthenticationError):  # a caller that gave up or a stranger
            continue
        last = time.monotonic()
        with contextlib.closing(connection):
            try:
                if not connection.poll(REQUEST_TIMEOUT):
                    continue
                method, args = connection.recv()
                if method == 'shutdown':
                    connection.send((True, 'bye'))
                    return
                if method == 'ping':
                    connection.send((True, 'pong'))
                elif method in GRAPH_METHODS:
                    connection.send((True, _answer(node, method, tuple(args))))
                else:
                    connection.send((False, f'unknown request {method!r}'))
            except Exception as error:  # one bad request never ends the daemon
                with contextlib.suppress(OSError):
                    connection.send((False, f'{type(error).__name__}: {error}'))


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(prog='ros2-daemon')
    parser.add_argument('--name', default='ros2-daemon')
    parser.add_argument('--ros-domain-id', type=int, default=domain_id())
    options = parser.parse_args(sys.argv[1:] if argv is None else argv)
    os.environ['ROS_DOMAIN_ID'] = str(options.ros_domain_id)
    try:
        listener = Listener(_address(), authkey=_authkey())
    except OSError:
        return  # another daemon already serves this domain
    import rclpy
    rclpy.init(args=[])
    try:
        node = rclpy.create_node(f'_ros2cli_daemon_{options.ros_domain_id}_{uuid.uuid4().hex}',
                                 start_parameter_services=False)
        serve(listener, node)
    except KeyboardInterrupt:
        pass
    finally:
        listener.close()
        rclpy.try_shutdown()
