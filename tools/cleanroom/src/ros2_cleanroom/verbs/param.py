"""`ros2 param list|get|set|dump|describe|delete|load`: a node's parameters through its
services."""
from __future__ import annotations

import argparse
import re
import sys

from rcl_interfaces.msg import ParameterDescriptor, ParameterValue
from rcl_interfaces.srv import DescribeParameters
from rclhelpers.services import call_service
from rclpy.node import Node

from ros2_cleanroom import cli_node, param_client, param_file, param_values
from ros2_cleanroom.discovery_options import add_discovery_options
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

    delete = add_verb(verbs, 'delete', 'Delete parameter', delete_param)
    delete.add_argument('node_name', help='Name of the ROS node')
    delete.add_argument('parameter_name', help='Name of the parameter')
    _add_node_options(delete)

    describe = add_verb(verbs, 'describe',
                        'Show descriptive information about declared parameters', describe_params)
    describe.add_argument('node_name', help='Name of the ROS node')
    describe.add_argument('parameter_names', nargs='+', help='Names of the parameters')
    _add_node_options(describe)

    load = add_verb(verbs, 'load', 'Load parameter file for a node', load_params)
    load.add_argument('node_name', help='Name of the ROS node')
    load.add_argument('parameter_file', help='Parameter file')
    _add_node_options(load, wildcard=True)
    return parser


def _add_node_options(parser: argparse.ArgumentParser, wildcard: bool = False) -> None:
    """The options Jazzy's delete, describe and load share, in its order."""
    add_discovery_options(parser)
    parser.add_argument('--include-hidden-nodes', action='store_true',
                        help='Consider hidden nodes as well')
    if wildcard:
        parser.add_argument('--no-use-wildcard', action='store_true',
                            help="Do not load parameters in the '/**' namespace into the node")
    parser.add_argument('--timeout', metavar='N', type=int, default=1,
                        help='Wait for N seconds until node becomes available (default 1 sec)')


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
    return _set_and_report(args, param_values.from_text(args.value),
                           'Set parameter successful', 'Setting parameter failed')


def _set_and_report(args: argparse.Namespace, value: ParameterValue, done: str,
                    failed: str) -> int:
    """Set one parameter (`set`, and `delete` with a value of type not set); Jazzy
    reports a refused value on stderr but still exits 0."""
    with cli_node.cli_node() as node:
        target = _find(node, args)
        if target is None:
            return fail('Node not found')
        try:
            result = param_client.set_value(node, target, args.parameter_name, value)
        except param_client.ParameterServiceError as error:
            return fail(str(error))
    if result.successful:
        print(done)
    elif result.reason:
        print(f'{failed}: {result.reason}', file=sys.stderr)
    else:
        print(failed, file=sys.stderr)
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


def delete_param(args: argparse.Namespace) -> int:
    """Unset the parameter (a value of type not set), reported as `set` reports."""
    return _set_and_report(args, ParameterValue(), 'Deleted parameter successfully',
                           'Deleting parameter failed')


def describe_params(args: argparse.Namespace) -> int:
    """Each descriptor the node gives; it gives none when one name is undeclared."""
    with cli_node.cli_node() as node:
        target = _find(node, args)
        if target is None:
            return fail('Node not found')
        request = DescribeParameters.Request(names=list(args.parameter_names))
        response = call_service(node, DescribeParameters, f'{target}/describe_parameters',
                                request)
        if response is None:
            return fail(str(param_client.ParameterServiceError(target)))
    for descriptor in response.descriptors:
        print(describe_descriptor(descriptor))
    return 0


def describe_descriptor(descriptor: ParameterDescriptor) -> str:
    """The block `ros2 param describe` prints for one parameter."""
    lines = [f'Parameter name: {descriptor.name}',
             f'  Type: {param_values.type_name(ParameterValue(type=descriptor.type))}']
    if descriptor.description:
        lines.append(f'  Description: {descriptor.description}')
    lines.append('  Constraints:')
    if descriptor.read_only:
        lines.append('    Read only: true')
    for bounds in (*descriptor.floating_point_range, *descriptor.integer_range):
        lines += [f'    Min value: {bounds.from_value}', f'    Max value: {bounds.to_value}']
        if bounds.step:
            lines.append(f'    Step: {bounds.step}')
    if descriptor.additional_constraints:
        lines.append(f'    Additional constraints: {descriptor.additional_constraints}')
    return '\n'.join(lines)


def load_params(args: argparse.Namespace) -> int:
    """Set every parameter of the file, one by one: successes on stdout, refusals on
    stderr, exit 0.  A file that cannot be read or parsed ends in its exception."""
    with cli_node.cli_node() as node:
        target = _find(node, args)
        if target is None:
            return fail('Node not found')
        try:
            values = param_file.read_parameter_file(args.parameter_file,
                                                    use_wildcard=not args.no_use_wildcard)
        except RuntimeError as error:
            return fail(str(error))
        for name, value in values.items():
            try:
                result = param_client.set_value(node, target, name,
                                                param_file.to_parameter_value(value))
            except param_client.ParameterServiceError as error:
                return fail(str(error))
            if result.successful:
                print(f'Set parameter {name} successful', flush=True)
            elif result.reason:
                print(f'Set parameter {name} failed: {result.reason}', file=sys.stderr,
                      flush=True)
            else:
                print(f'Set parameter {name} failed', file=sys.stderr, flush=True)
    return 0


def main(argv: list[str]) -> int:
    return run(build_parser(), argv)
