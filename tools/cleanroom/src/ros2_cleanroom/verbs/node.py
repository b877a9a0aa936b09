"""`ros2 node list|info`: the nodes in the graph and what each one offers."""
from __future__ import annotations

import argparse
import sys

from rclhelpers.names import full_name, is_hidden, split_full_name
from rclpy.action.graph import (
    get_action_client_names_and_types_by_node,
    get_action_server_names_and_types_by_node,
)
from rclpy.node import Node

from ros2_cleanroom import cli_node
from ros2_cleanroom.verb_args import add_spin_time, add_verb, command_parser, fail, run


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('node', 'Various node related sub-commands')
    listing = add_verb(verbs, 'list', 'Output a list of available nodes', list_nodes)
    listing.add_argument('-a', '--all', action='store_true',
                         help='Display all nodes even hidden ones')
    listing.add_argument('-c', '--count-nodes', action='store_true',
                         help='Only display the number of nodes discovered')
    add_spin_time(listing)
    info = add_verb(verbs, 'info', 'Output information about a node', node_info)
    info.add_argument('node_name', help='Node name to request information')
    info.add_argument('--include-hidden', action='store_true',
                      help='Display hidden topics, services, and actions as well')
    add_spin_time(info)
    return parser


def _max_wait(args: argparse.Namespace) -> float:
    return args.spin_time if args.spin_time is not None else cli_node.MAX_WAIT


#: Jazzy's words when two nodes in the graph have the same full name (on standard error).
SHARED_NAME = ('WARNING: Be aware that there are nodes in the graph that share an exact name, '
               'which can have unintended side effects.')


def list_nodes(args: argparse.Namespace) -> int:
    """Every node once per node, as Jazzy lists them: two nodes with one name are
    two lines (and counted twice), followed by a warning about them."""
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node, max_wait=_max_wait(args))
        names = sorted(name for name in (full_name(n, ns) for n, ns
                                         in node.get_node_names_and_namespaces())
                       if args.all or not is_hidden(name))
    if args.count_nodes:
        print(len(names))
        return 0
    for name in names:
        print(name)
    if len(set(names)) < len(names):
        print(SHARED_NAME, file=sys.stderr)
    return 0


def node_info(args: argparse.Namespace) -> int:
    target = args.node_name if args.node_name.startswith('/') else '/' + args.node_name
    with cli_node.graph_node(args) as node:
        if not cli_node.wait_for_node(node, target, include_hidden=True,
                                      max_wait=_max_wait(args)):
            return fail(f"Unable to find node '{args.node_name}'")
        sections = node_sections(node, target, args.include_hidden)
    print(target)
    for title, entries in sections:
        print(f'  {title}:')
        print('\n'.join('    {}: {}'.format(name, ', '.join(types)) for name, types in entries))
    return 0


def node_sections(node: Node, target: str,
                  include_hidden: bool) -> list[tuple[str, list[tuple[str, list[str]]]]]:
    """The six sections of `ros2 node info`, each a sorted list of (name, types)."""
    name, namespace = split_full_name(target)
    queries = [
        ('Subscribers', node.get_subscriber_names_and_types_by_node),
        ('Publishers', node.get_publisher_names_and_types_by_node),
        ('Service Servers', node.get_service_names_and_types_by_node),
        ('Service Clients', node.get_client_names_and_types_by_node),
        # the daemon's graph answers these itself; a node of our own goes through rclpy
        ('Action Servers',
         getattr(node, 'get_action_server_names_and_types_by_node', None)
         or (lambda n, ns: get_action_server_names_and_types_by_node(node, n, ns))),
        ('Action Clients',
         getattr(node, 'get_action_client_names_and_types_by_node', None)
         or (lambda n, ns: get_action_client_names_and_types_by_node(node, n, ns))),
    ]
    sections = []
    for title, query in queries:
        entries = sorted((entry_name, list(types)) for entry_name, types in query(name, namespace)
                         if include_hidden or not is_hidden(entry_name))
        sections.append((title, entries))
    return sections


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
