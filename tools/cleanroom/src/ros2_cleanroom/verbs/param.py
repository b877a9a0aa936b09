"""`ros2 param list|get|set|dump`: a node's parameters through its services."""
from __future__ import annotations

import argparse
import re
import sys

from rclpy.node import Node

from ros2_cleanroom import cli_node, param_client, param_values
from ros2_cleanroom.verb_args import add_spin_time, add_verb, command_parser, fail, run


def build_parser() -> argparse.ArgumentParser:
    parser, verbs = command_parser('param', 'Various param related sub-commands')

    listing = add_verb(verbs, 'list', 'Output a list of available parameters', list_params)
    listing.add_argument('node_name', nargs='?', help='Name of the ROS node')
    listing.add_argument('--include-hidden-nodes', action='store_true',
                         help='Consider hidden nodes as well')
    listing.add_argument('--param-prefixes', nargs='+', default=[],
                         help='Only list parameters with the provided prefixes')
    listing.add_argument('--filter', default=None,
                         help='Only list parameters whose name matches this regular expression')
    listing.add_argument('--param-type', action='store_true',
                         help='Print parameter types with parameter names')
    add_spin_time(listing)

    get = add_verb(verbs, 'get', 'Get parameter', get_param)
    get.add_argument('node_name', help='Name of the ROS node')
    get.add_argument('parameter_name', help='Name of the parameter')
    get.add_argument('--include-hidden-nodes', action='store_true',
                     help='Consider hidden nodes as well')
    get.add_argument('--hide-type', action='store_true',
                     help='Hide the type information')
    add_spin_time(get)

    set_ = add_verb(verbs, 'set', 'Set parameter', set_param)
    set_.add_argument('node_name', help='Name of the ROS node')
    set_.add_argument('parameter_name', help='Name of the parameter')
    set_.add_argument('value', help='Value of the parameter (parsed as YAML)')
    set_.add_argument('--include-hidden-nodes', action='store_true',
                      help='Consider hidden nodes as well')
    add_spin_time(set_)

    dump = add_verb(verbs, 'dump', 'Show all of the parameters of a node in a YAML file format',
                    dump_params)
    dump.add_argument('node_name', help='Name of the ROS node')
    dump.add_argument('--include-hidden-nodes', action='store_true',
                      help='Consider hidden nodes as well')
    add_spin_time(dump)
    return parser


def _absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name


def _max_wait(args: argparse.Namespace) -> float:
    return args.spin_time if args.spin_time is not None else cli_node.MAX_WAIT


def _find(node: Node, args: argparse.Namespace) -> str | None:
    """The target node's full name once discovered, or None."""
    target = _absolute(args.node_name)
    found = cli_node.wait_for_node(node, target, include_hidden=args.include_hidden_nodes,
                                   max_wait=_max_wait(args))
    return target if found else None


def list_params(args: argparse.Namespace) -> int:
    pattern = re.compile(args.filter) if args.filter else None
    with cli_node.cli_node() as node:
        if args.node_name:
            target = _find(node, args)
            if target is None:
                return fail('Node not found')
            targets = [target]
        else:
            cli_node.wait_for_graph(node, max_wait=_max_wait(args))
            targets = cli_node.node_names(node, include_hidden=args.include_hidden_nodes)
        listings = []
        for target in targets:
            try:
                names = param_client.list_names(node, target, args.param_prefixes)
                names = [n for n in names if not pattern or pattern.search(n)]
                if args.param_type:
                    names = _with_types(node, target, names)
            except param_client.ParameterServiceError as error:
                if args.node_name:
                    return fail(str(error))
                continue  # a node without parameter services is left out
            listings.append((target, names))
    for target, names in listings:
        if not args.node_name:
            print(f'{target}:')
        for name in names:
            print(f'  {name}')
    return 0


def _with_types(node: Node, target: str, names: list[str]) -> list[str]:
    """`name (type: double)` for each name, as `--param-type` lists them."""
    values = param_client.get_values(node, target, names) if names else []
    return [f'{name} (type: {param_values.type_name(value)})'
            for name, value in zip(names, values, strict=True)]


def get_param(args: argparse.Namespace) -> int:
    with cli_node.cli_node() as node:
        target = _find(node, args)
        if target is None:
            return fail('Node not found')
        try:
            [value] = param_client.get_values(node, target, [args.parameter_name])
        except param_client.ParameterServiceError as error:
            return fail(str(error))
        except ValueError:  # the node answered with no value at all
            return fail('Parameter not set')
    line = param_values.describe(value, hide_type=args.hide_type)
    if line is None:
        return fail('Parameter not set')
    print(line)
    return 0


def set_param(args: argparse.Namespace) -> int:
    value = param_values.from_text(args.value)
    with cli_node.cli_node() as node:
        target = _find(node, args)
        if target is None:
            return fail('Node not found')
        try:
            result = param_client.set_value(node, target, args.parameter_name, value)
        except param_client.ParameterServiceError as error:
            return fail(str(error))
    # Jazzy reports a refused value on stderr but still exits 0.
    if result.successful:
        print('Set parameter successful')
    elif result.reason:
        print(f'Setting parameter failed: {result.reason}', file=sys.stderr)
    else:
        print('Setting parameter failed', file=sys.stderr)
    return 0


def dump_params(args: argparse.Namespace) -> int:
    with cli_node.cli_node() as node:
        target = _find(node, args)
        if target is None:
            return fail('Node not found')
        try:
            names = param_client.list_names(node, target)
            values = param_client.get_values(node, target, names)
        except param_client.ParameterServiceError as error:
            return fail(str(error))
    flat = {name: param_values.to_python(value) for name, value in zip(names, values, strict=True)}
    print(param_values.dump_yaml(target, flat))
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
