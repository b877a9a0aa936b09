"""`ros2 action info|list|send_goal|type`: the actions in the graph, and sending a goal."""
from __future__ import annotations

import argparse
import sys

from ros2_cleanroom import cli_node
from ros2_cleanroom.action_goal import send_goal
from ros2_cleanroom.action_graph import action_endpoints, action_names_and_types
from ros2_cleanroom.interfaces import import_interface
from ros2_cleanroom.message_fields import fill_from_yaml
from ros2_cleanroom.verb_args import add_verb, command_parser, fail, run

_NAME_HELP = "Name of the ROS action to get info (e.g. '/fibonacci')"


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('action', 'Various action related sub-commands')
    info = add_verb(verbs, 'info', 'Print information about an action', action_info)
    info.add_argument('action_name', help=_NAME_HELP)
    info.add_argument('-t', '--show-types', action='store_true',
                      help='Additionally show the action type')
    info.add_argument('-c', '--count', action='store_true',
                      help='Only display the number of action clients and action servers')
    listing = add_verb(verbs, 'list', 'Output a list of action names', list_actions)
    listing.add_argument('-t', '--show-types', action='store_true',
                         help='Additionally show the action type')
    listing.add_argument('-c', '--count-actions', action='store_true',
                         help='Only display the number of actions discovered')
    goal = add_verb(verbs, 'send_goal', 'Send an action goal', action_send_goal)
    goal.set_defaults(parser=goal)
    goal.add_argument('action_name', help="Name of the ROS action (e.g. '/fibonacci')")
    goal.add_argument('action_type',
                      help="Type of the ROS action (e.g. 'example_interfaces/action/Fibonacci')")
    goal.add_argument('goal', nargs='?',
                      help="Goal request values in YAML format (e.g. '{order: 10}')")
    goal.add_argument('--stdin', action='store_true', help='Read goal from standard input')
    goal.add_argument('-f', '--feedback', action='store_true',
                      help='Echo feedback messages for the goal')
    kind = add_verb(verbs, 'type', "Print a action's type", action_type)
    kind.add_argument('action_name', help=_NAME_HELP)
    return parser


def list_actions(args: argparse.Namespace) -> int:
    with cli_node.graph_node(args) as node:
        cli_node.wait_for_graph(node)
        actions = action_names_and_types(node)
    if args.count_actions:
        print(len(actions))
        return 0
    for name, types in actions:
        print(f"{name} [{', '.join(types)}]" if args.show_types else name)
    return 0


def action_info(args: argparse.Namespace) -> int:
    """Clients and servers of the action; an unknown action has none of either.

    The name is looked up as an absolute name (`fibonacci` is `/fibonacci`) but
    printed as given.
    """
    target = args.action_name if args.action_name.startswith('/') else '/' + args.action_name
    with cli_node.graph_node(args) as node:
        cli_node.wait_until(node, lambda: target in dict(action_names_and_types(node)))
        clients, servers = action_endpoints(node, target)
    print(f'Action: {args.action_name}')
    for title, entries in (('Action clients', clients), ('Action servers', servers)):
        print(f'{title}: {len(entries)}')
        if args.count:
            continue
        for name, types in entries:
            print(f"    {name} [{', '.join(types)}]" if args.show_types else f'    {name}')
    return 0


def action_type(args: argparse.Namespace) -> int:
    """The action's types, one a line; an unknown action fails silently.

    The name is taken as given: `fibonacci` is not `/fibonacci`.
    """
    with cli_node.graph_node(args) as node:
        cli_node.wait_until(node, lambda: args.action_name in dict(action_names_and_types(node)))
        types = dict(action_names_and_types(node)).get(args.action_name)
    if not types:
        return 1
    for name in types:
        print(name)
    return 0


def action_send_goal(args: argparse.Namespace) -> int:
    if args.stdin and args.goal is not None:
        args.parser.error('argument goal: not allowed with argument --stdin')
    try:
        action_class = import_interface(args.action_type, kind='action')
    except ValueError:
        return fail('The passed action type is invalid')
    text = sys.stdin.read() if args.stdin else args.goal
    goal = action_class.Goal()
    if text is not None:
        try:
            fill_from_yaml(goal, text)
        except Exception as error:  # noqa: BLE001 - reported as Jazzy does
            return fail(f'Failed to populate message fields: {error!r}')
    return send_goal(args.action_name, action_class, args.action_type, goal, args.feedback)


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
