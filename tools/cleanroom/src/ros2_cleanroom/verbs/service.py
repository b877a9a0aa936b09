"""`ros2 service list|type|find|info|call|echo`: the services in the graph, calling one and
echoing its introspection events (ros2_cleanroom.service_echo)."""
from __future__ import annotations

import argparse
import sys
import time

from rclhelpers.names import is_hidden
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

from ros2_cleanroom import cli_node
from ros2_cleanroom.discovery_options import add_discovery_options
from ros2_cleanroom.interfaces import import_interface
from ros2_cleanroom.message_fields import fill_from_yaml
from ros2_cleanroom.service_echo import add_arguments as add_echo_arguments
from ros2_cleanroom.service_echo import echo_service
from ros2_cleanroom.verb_args import add_verb, command_parser, fail, run

_HIDDEN_HELP = 'Consider hidden services as well'


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('service', 'Various service related sub-commands')
    parser.add_argument('--include-hidden-services', action='store_true',
                        dest='hidden_services', help=_HIDDEN_HELP)
    call = add_verb(verbs, 'call', 'Call a service', service_call)
    call.set_defaults(parser=call)
    call.add_argument('service_name',
                      help="Name of the ROS service to call to (e.g. '/add_two_ints')")
    call.add_argument('service_type',
                      help="Type of the ROS service (e.g. 'std_srvs/srv/Empty')")
    call.add_argument('values', nargs='?',
                      help="Values to fill the service request with in YAML format (e.g. "
                           "'{a: 1, b: 2}'), otherwise the service request will be published "
                           'with default values')
    call.add_argument('--stdin', action='store_true', help='Read values from standard input')
    call.add_argument('-r', '--rate', metavar='N', type=float,
                      help='Repeat the call at a specific rate in Hz')
    add_echo_arguments(add_verb(verbs, 'echo', 'Echo a service', echo_service))
    find = add_verb(verbs, 'find', 'Output a list of available services of a given type',
                    find_services)
    find.add_argument('service_type', help="Name of the ROS service type to filter for (e.g. "
                                           "'rcl_interfaces/srv/ListParameters')")
    find.add_argument('-c', '--count-services', action='store_true',
                      help='Only display the number of services discovered')
    find.add_argument('--include-hidden-services', action='store_true', help=_HIDDEN_HELP)
    info = add_verb(verbs, 'info', 'Print information about a service', service_info)
    add_discovery_options(info)
    info.add_argument('service_name',
                      help="Name of the ROS service to get info (e.g. '/add_two_ints')")
    listing = add_verb(verbs, 'list', 'Output a list of available services', list_services)
    add_discovery_options(listing)
    listing.add_argument('-t', '--show-types', action='store_true',
                         help='Additionally show the service type')
    listing.add_argument('-c', '--count-services', action='store_true',
                         help='Only display the number of services discovered')
    listing.add_argument('--include-hidden-services', action='store_true', help=_HIDDEN_HELP)
    kind = add_verb(verbs, 'type', "Output a service's type", service_type)
    kind.add_argument('service_name', help="Name of the ROS service to get type (e.g. "
                                           "'/talker/list_parameters')")
    return parser


def _max_wait(args: argparse.Namespace) -> float:
    spin_time = getattr(args, 'spin_time', None)
    return spin_time if spin_time is not None else cli_node.MAX_WAIT


def _include_hidden(args: argparse.Namespace) -> bool:
    return args.hidden_services or getattr(args, 'include_hidden_services', False)


def _services(node: Node, include_hidden: bool) -> list[tuple[str, list[str]]]:
    return sorted((name, list(types)) for name, types in node.get_service_names_and_types()
                  if include_hidden or not is_hidden(name))


def list_services(args: argparse.Namespace) -> int:
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node, max_wait=_max_wait(args))
        services = _services(node, _include_hidden(args))
    if args.count_services:
        print(len(services))
        return 0
    for name, types in services:
        print(f"{name} [{', '.join(types)}]" if args.show_types else name)
    return 0


def service_type(args: argparse.Namespace) -> int:
    """The service's types, one a line; an unknown service fails silently.

    The name is taken as given: `talker/x` is not `/talker/x`.
    """
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(
            node, until=lambda: args.service_name in dict(_services(node, True)))
        types = dict(_services(node, True)).get(args.service_name)
    if not types:
        return 1
    for name in types:
        print(name)
    return 0


def find_services(args: argparse.Namespace) -> int:
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node)
        services = [name for name, types in _services(node, _include_hidden(args))
                    if args.service_type in types]
    if args.count_services:
        print(len(services))
        return 0
    for name in services:
        print(name)
    return 0


def _endpoint_count(node: Node, service: str, by_node: str) -> int:
    """How many servers (or clients) of `service` the nodes in the graph have."""
    count = 0
    for name, namespace in node.get_node_names_and_namespaces():
        try:
            entries = getattr(node, by_node)(name, namespace)
        except Exception:  # noqa: BLE001 - the node may vanish meanwhile
            continue
        count += sum(1 for entry_name, _ in entries if entry_name == service)
    return count


def service_info(args: argparse.Namespace) -> int:
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node, max_wait=_max_wait(args),
                                until=lambda: args.service_name in dict(_services(node, True)))
        types = dict(_services(node, True)).get(args.service_name)
        if not types:
            return fail(f"Unknown service '{args.service_name}'")
        clients = _endpoint_count(node, args.service_name, 'get_client_names_and_types_by_node')
        servers = _endpoint_count(node, args.service_name, 'get_service_names_and_types_by_node')
    print(f"Type: {', '.join(types)}")
    print(f'Clients count: {clients}')
    print(f'Services count: {servers}')
    return 0


def service_call(args: argparse.Namespace) -> int:
    if args.stdin and args.values is not None:
        args.parser.error('argument values: not allowed with argument --stdin')
    try:
        srv_type = import_interface(args.service_type, kind='srv')
    except ValueError:
        return fail('The passed service type is invalid')
    text = sys.stdin.read() if args.stdin else args.values
    request = srv_type.Request()
    if text is not None:
        try:
            fill_from_yaml(request, text)
        except Exception as error:  # noqa: BLE001 - reported as ros2cli does
            return fail(f'Failed to populate field: {error}')
    period = 1.0 / args.rate if args.rate else None
    with cli_node.cli_node('_ros2cli_requester') as node:
        client = node.create_client(srv_type, args.service_name)
        executor = SingleThreadedExecutor(context=node.context)
        executor.add_node(node)
        if not client.service_is_ready():
            print('waiting for service to become available...', flush=True)
            while not client.wait_for_service(timeout_sec=1.0):
                pass
        while True:
            started = time.monotonic()
            print(f'requester: making request: {request!r}\n', flush=True)
            future = client.call_async(request)
            while not future.done():  # as long as it takes, as Jazzy waits (Ctrl-C ends it)
                executor.spin_once(timeout_sec=0.1)
            print('response:')
            print(f'{future.result()!r}\n', flush=True)
            if period is None:
                return 0
            time.sleep(max(0.0, period - (time.monotonic() - started)))


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
