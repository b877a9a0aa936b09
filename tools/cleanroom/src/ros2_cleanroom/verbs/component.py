"""`ros2 component list|load|standalone|types|unload`: components and their containers.

Containers are found in the graph (ros2_cleanroom.component_containers) and
driven through their composition_interfaces services; `types` reads the
ament index; `standalone` starts rclcpp_components' `component_container`
and loads the component into it.
"""
from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import uuid

from ament_index_python.packages import PackageNotFoundError, get_package_prefix

from ros2_cleanroom import cli_node
from ros2_cleanroom.component_containers import (
    call,
    container_names,
    list_components,
    service_types,
    wait_for,
)
from ros2_cleanroom.component_index import (
    PackageNotFound,
    package_component_types,
    registered_component_types,
)
from ros2_cleanroom.component_params import parameters
from ros2_cleanroom.discovery_options import add_discovery_options
from ros2_cleanroom.verb_args import add_verb, command_parser, fail, run

#: How long `standalone` waits for its container's load_node service (seconds).
STANDALONE_WAIT = 5.0


def _add_component_options(parser: argparse.ArgumentParser) -> None:
    """The positionals and options `load` and `standalone` share, in Jazzy's order."""
    parser.add_argument('package_name',
                        help='Name of the package where the component is to be found')
    parser.add_argument('plugin_name', help='Type name of the component to be loaded')
    parser.add_argument('-n', '--node-name', default=None, help='Component node name')
    parser.add_argument('--node-namespace', default=None, help='Component node namespace')
    parser.add_argument('--log-level', default=None, help='Component node log level')
    parser.add_argument('-r', '--remap-rule', action='append', default=None,
                        dest='remap_rules',
                        help="Component node remapping rules, in the 'from:=to' form")
    parser.add_argument('-p', '--parameter', action='append', default=None, dest='parameters',
                        help="Component node parameters, in the 'name:=value' form")
    parser.add_argument('-e', '--extra-argument', action='append', default=None,
                        dest='extra_arguments',
                        help="Extra arguments for the container, in the 'name:=value' form")


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('component', 'Various component related sub-commands')
    listing = add_verb(verbs, 'list', 'Output a list of running containers and components',
                       list_containers)
    add_discovery_options(listing)
    listing.add_argument('container_node_name', nargs='?', default=None,
                         help='Name of the container node to list components from')
    listing.add_argument('--containers-only', action='store_true',
                         help='List found containers nodes only')
    load = add_verb(verbs, 'load', 'Load a component into a container node', load_component)
    add_discovery_options(load)
    load.add_argument('container_node_name',
                      help='Container node name to load component into')
    _add_component_options(load)
    load.add_argument('-q', '--quiet', action='store_true',
                      help='Only print component unique IDs and names')
    standalone = add_verb(verbs, 'standalone',
                          'Run a component into its own standalone container node',
                          run_standalone)
    add_discovery_options(standalone)
    _add_component_options(standalone)
    standalone.add_argument('-c', '--container-node-name', default=None,
                            help='Name of the standalone container node to be run')
    types = add_verb(verbs, 'types', 'Output a list of components registered in the ament index',
                     list_types)
    types.add_argument('package_name', nargs='?', default=None,
                       help='Package name to look for registered components in')
    unload = add_verb(verbs, 'unload', 'Unload a component from a container node',
                      unload_components)
    add_discovery_options(unload)
    unload.add_argument('container_node_name',
                        help='Container node name to unload component from')
    unload.add_argument('component_uid', type=int, nargs='+',
                        help='Unique ID of the component to be unloaded')
    unload.add_argument('-q', '--quiet', action='store_true',
                        help='Only print component unique IDs')
    return parser


def _max_wait(args: argparse.Namespace) -> float:
    return args.spin_time if args.spin_time is not None else cli_node.MAX_WAIT


def _found_containers(args: argparse.Namespace, target: str | None = None) -> list[str]:
    """The containers in the graph: all of them once discovery settled, or (given
    `target`) as soon as that one shows up."""
    with cli_node.graph_node(args) as graph:
        if target is None:
            cli_node.wait_for_graph(graph, max_wait=_max_wait(args))
        else:
            cli_node.wait_until(graph, lambda: target in container_names(graph),
                                max_wait=_max_wait(args))
        return container_names(graph)


def _not_found(name: str) -> int:
    return fail(f"Unable to find container node '{name}'")


def list_containers(args: argparse.Namespace) -> int:
    target = args.container_node_name
    containers = _found_containers(args, target)
    if target is not None and target not in containers:
        return _not_found(target)
    if args.containers_only:
        if target is None:
            for name in containers:
                print(name)
        return 0
    with cli_node.cli_node() as node:
        if target is not None:
            for uid, name in list_components(node, target):
                print(f'{uid}  {name}')
            return 0
        for container in containers:
            print(container)
            for uid, name in list_components(node, container):
                print(f'  {uid}  {name}')
    return 0


def _load_request(srv: object, args: argparse.Namespace) -> object:
    """The LoadNode request, fields as given (a bad --log-level fails when sent)."""
    request = srv.LoadNode.Request()  # type: ignore[attr-defined]
    request.package_name = args.package_name
    request.plugin_name = args.plugin_name
    if args.node_name:
        request.node_name = args.node_name
    if args.node_namespace:
        request.node_namespace = args.node_namespace
    if args.log_level:
        request.log_level = args.log_level
    if args.remap_rules:
        request.remap_rules = args.remap_rules
    request.parameters = parameters(args.parameters)
    request.extra_arguments = parameters(args.extra_arguments)
    return request


def _load(node: object, container: str, args: argparse.Namespace) -> object:
    srv = service_types()
    return call(node, srv.LoadNode, f'{container}/_container/load_node',  # type: ignore[arg-type]
                _load_request(srv, args))


def load_component(args: argparse.Namespace) -> int:
    container = args.container_node_name
    if container not in _found_containers(args, container):
        return _not_found(container)
    with cli_node.cli_node() as node:
        response = _load(node, container, args)
    if not response.success:
        return fail(f'Failed to load component: {response.error_message}')
    if args.quiet:
        print(f'{response.unique_id}  {response.full_node_name}')
    else:
        print(f"Loaded component {response.unique_id} into '{container}' "
              f"container node as '{response.full_node_name}'")
    return 0


def unload_components(args: argparse.Namespace) -> int:
    container = args.container_node_name
    if container not in _found_containers(args, container):
        return _not_found(container)
    srv = service_types()
    failed = False
    with cli_node.cli_node() as node:
        for uid in args.component_uid:
            response = call(node, srv.UnloadNode, f'{container}/_container/unload_node',
                            srv.UnloadNode.Request(unique_id=uid))
            if not response.success:
                failed = True
                print(f"Failed to unload component {uid} from '{container}' container node\n"
                      f'    {response.error_message}', file=sys.stderr)
            elif args.quiet:
                print(uid)
            else:
                print(f"Unloaded component {uid} from '{container}' container node")
    return 1 if failed else 0


def list_types(args: argparse.Namespace) -> int:
    if args.package_name is None:
        for package, types in registered_component_types():
            print(package)
            print('\n'.join('  ' + name for name in types))
        return 0
    try:
        types = package_component_types(args.package_name)
    except PackageNotFound:
        return fail(f"Unable to find package '{args.package_name}'")
    print('\n'.join(types))
    return 0


def _container_executable() -> str | None:
    """rclcpp_components' component_container (where `ros2 run` finds it); None when
    that package has none.  Raises PackageNotFoundError without the package."""
    prefix = get_package_prefix('rclcpp_components')
    path = os.path.join(prefix, 'lib', 'rclcpp_components', 'component_container')
    return path if os.path.isfile(path) and os.access(path, os.X_OK) else None


def run_standalone(args: argparse.Namespace) -> int:
    """Start a container, load the component into it, and wait for the container
    (Ctrl-C reaches it too); its exit code is the command's."""
    try:
        executable = _container_executable()
    except PackageNotFoundError:
        return fail("Package 'rclcpp_components' not found")
    if executable is None:
        return fail('No component container node found!')
    name = args.container_node_name or 'standalone_container_' + uuid.uuid4().hex[:12]
    container = subprocess.Popen([executable, '--ros-args', '-r', f'__node:={name}'])
    try:
        with cli_node.cli_node() as node:
            problem = _load_into_standalone(node, name, args)
        if problem is not None:
            print(f'{problem}, interrupting container node', flush=True)
            container.send_signal(signal.SIGINT)
        return container.wait()
    except KeyboardInterrupt:
        return container.wait()


def _load_into_standalone(node: object, name: str, args: argparse.Namespace) -> str | None:
    """Load the component once the container's service is up; what went wrong, if anything."""
    srv = service_types()
    client = node.create_client(srv.LoadNode, f'{name}/_container/load_node')  # type: ignore[attr-defined]
    if not client.wait_for_service(timeout_sec=STANDALONE_WAIT):
        return f"No 'load_node' service found for '{name}' container"
    response = wait_for(node, client.call_async(_load_request(srv, args)))  # type: ignore[arg-type]
    if not response.success:
        return f'Failed to load component: {response.error_message}'
    return None


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
