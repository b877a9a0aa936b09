"""`ros2 lifecycle get|list|nodes|set`: the lifecycle nodes in the graph, their states and
transitions."""
from __future__ import annotations

import argparse
import sys

from ros2_cleanroom import cli_node, lifecycle_client
from ros2_cleanroom.discovery_options import add_discovery_options
from ros2_cleanroom.verb_args import add_verb, command_parser, fail, run

_HIDDEN_HELP = 'Consider hidden nodes as well'


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('lifecycle', 'Various lifecycle related sub-commands')
    get = add_verb(verbs, 'get', 'Get lifecycle state for one or more nodes', lifecycle_get)
    add_discovery_options(get)
    get.add_argument('--include-hidden-nodes', action='store_true', help=_HIDDEN_HELP)
    get.add_argument('node_name', nargs='?',
                     help='Name of the ROS node. If no name is provided, then get the state '
                          'for all nodes.')
    listing = add_verb(verbs, 'list', 'Output a list of available transitions', lifecycle_list)
    add_discovery_options(listing)
    listing.add_argument('--include-hidden-nodes', action='store_true', help=_HIDDEN_HELP)
    listing.add_argument('node_name', help='Name of the ROS node')
    listing.add_argument('-a', '--all', action='store_true',
                         help='Display all existing transitions')
    nodes = add_verb(verbs, 'nodes', 'Output a list of nodes with lifecycle', lifecycle_nodes)
    add_discovery_options(nodes)
    nodes.add_argument('-a', '--all', action='store_true',
                       help='Display all nodes even hidden ones')
    nodes.add_argument('-c', '--count-nodes', action='store_true',
                       help='Only display the number of nodes discovered')
    setter = add_verb(verbs, 'set', 'Trigger lifecycle state transition', lifecycle_set)
    add_discovery_options(setter)
    setter.add_argument('--include-hidden-nodes', action='store_true', help=_HIDDEN_HELP)
    setter.add_argument('node_name', help='Name of the ROS node')
    setter.add_argument('transition', help='The lifecycle transition')
    return parser


def _max_wait(args: argparse.Namespace) -> float:
    return args.spin_time if args.spin_time is not None else cli_node.MAX_WAIT


def _absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name


def lifecycle_nodes(args: argparse.Namespace) -> int:
    with cli_node.graph_node(args) as graph:
        cli_node.wait_for_graph(graph, max_wait=_max_wait(args))
        names = lifecycle_client.lifecycle_nodes(graph, args.all)
    if args.count_nodes:
        print(len(names))
        return 0
    for name in names:
        print(name)
    return 0


def lifecycle_get(args: argparse.Namespace) -> int:
    """One node's state, or every lifecycle node's state prefixed with its name."""
    hidden = args.include_hidden_nodes
    with cli_node.graph_node(args) as graph:
        if args.node_name is None:
            cli_node.wait_for_graph(graph, max_wait=_max_wait(args))
            targets = lifecycle_client.lifecycle_nodes(graph, hidden)
        else:
            targets = [_absolute(args.node_name)]
            if not _wait_for_lifecycle_node(graph, targets[0], args):
                return fail('Node not found')
        with lifecycle_client.caller(graph) as node:
            states = [(target, lifecycle_client.get_state(node, target)) for target in targets]
    for target, state in states:
        prefix = f'{target}: ' if args.node_name is None else ''
        print(f'{prefix}{state.label} [{state.id}]')
    return 0


def lifecycle_list(args: argparse.Namespace) -> int:
    target = _absolute(args.node_name)
    with cli_node.graph_node(args) as graph:
        if not _wait_for_lifecycle_node(graph, target, args):
            return fail('Node not found')
        with lifecycle_client.caller(graph) as node:
            found = lifecycle_client.transitions(node, target, graph=args.all)
    for description in found:
        print(f'- {description.transition.label} [{description.transition.id}]\n'
              f'\tStart: {description.start_state.label}\n'
              f'\tGoal: {description.goal_state.label}')
    return 0


def lifecycle_set(args: argparse.Namespace) -> int:
    """Trigger the transition named by its label or its number, if it is available now.

    A transition the node refuses is reported on standard error, yet exits 0
    (as Jazzy's does).
    """
    target = _absolute(args.node_name)
    with cli_node.graph_node(args) as graph:
        if not _wait_for_lifecycle_node(graph, target, args):
            return fail('Node not found')
        with lifecycle_client.caller(graph) as node:
            available = [description.transition for description
                         in lifecycle_client.transitions(node, target)]
            chosen = next((transition for transition in available
                           if args.transition in (transition.label, str(transition.id))), None)
            if chosen is None:
                return fail('\n'.join(
                    ['Unknown transition requested, available ones are:']
                    + [f'- {transition.label} [{transition.id}]' for transition in available]))
            succeeded = lifecycle_client.change_state(node, target, chosen)
    if not succeeded:
        print('Transitioning failed', file=sys.stderr)
        return 0
    print('Transitioning successful')
    return 0


def _wait_for_lifecycle_node(graph: object, target: str, args: argparse.Namespace) -> bool:
    """Wait until `target` shows up as a lifecycle node; False if it never does."""
    def found() -> bool:
        return target in lifecycle_client.lifecycle_nodes(graph, args.include_hidden_nodes)
    cli_node.wait_until(graph, found, max_wait=_max_wait(args))
    return found()


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
