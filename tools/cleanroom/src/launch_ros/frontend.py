"""The tags and substitutions launch_ros adds to the XML / YAML front ends.

Imported by `launch.frontend.Parser` through the `launch.frontend.launch_extension`
entry point, so that `launch` never imports launch_ros.
"""
from __future__ import annotations

from typing import Any

from launch.frontend.entity import Entity
from launch.frontend.expose import (
    register_action_parse_method,
    register_substitution_parse_method,
)
from launch.frontend.launch_actions import (
    nested,
    parse_command,
    parse_condition,
    parse_process,
)
from launch.frontend.launch_substitutions import check_count
from launch.frontend.parse_substitution import has_substitutions

from .actions import Node, PushRosNamespace, SetParameter, SetRemap
from .parameter_descriptions import ParameterFile, ParameterValue
from .substitutions import ExecutableInPackage, FindPackagePrefix, FindPackageShare

Parsed = tuple[type, dict[str, Any]]

PARAMETER_TYPES = {'str': str, 'int': int, 'float': float, 'bool': bool}


def plain_or_substitutions(value: Any, parser: Any) -> Any:
    """Text with `$(...)` becomes substitutions (typed as YAML when the node starts);
    plain text and typed values stay as they are (text stays text)."""
    if isinstance(value, list):
        return [plain_or_substitutions(item, parser) for item in value]
    if not isinstance(value, str):
        return value
    substitutions = parser.parse_substitution(value)
    return substitutions if has_substitutions(substitutions) else value


def parse_parameter_value(param: Entity, parser: Any) -> Any:
    """The value of `<param name value [type] [value-sep]/>`."""
    type_name = param.get_attr('type', optional=True)
    if type_name is None:
        return plain_or_substitutions(param.get_attr('value', data_type=None), parser)
    if type_name not in PARAMETER_TYPES:
        raise ValueError(f"Unknown parameter type '{type_name}' in `param`, expected one "
                         f'of {sorted(PARAMETER_TYPES)}')
    text = param.get_attr('value', data_type=str)
    value = parser.parse_substitution(text) if isinstance(text, str) else text
    return ParameterValue(value, value_type=PARAMETER_TYPES[type_name])


def parse_parameters(params: list[Entity], parser: Any) -> list[Any]:
    """`<param>` entities: each a dict of its own (nested ones grouped), or a file."""
    result: list[Any] = []
    for param in params:
        path = param.get_attr('from', optional=True)
        if path is not None:
            allow_substs = param.get_attr('allow_substs', data_type=bool, optional=True)
            file = parser.parse_substitution(path)
            result.append(file if allow_substs is None
                          else ParameterFile(file, allow_substs=allow_substs))
        else:
            result.append(parse_parameter_dict([param], parser))
        param.assert_entity_completely_parsed()
    return result


def parse_parameter_dict(params: list[Entity], parser: Any) -> dict[str, Any]:
    """`{name: value}` of params, nested `<param name><param .../></param>` as nested dicts."""
    values: dict[str, Any] = {}
    for param in params:
        name = param.get_attr('name')
        children = nested(param, 'param')
        if children:
            values[name] = parse_parameter_dict(children, parser)
        else:
            values[name] = parse_parameter_value(param, parser)
        param.assert_entity_completely_parsed()
    return values


def parse_remappings(entity: Entity, parser: Any) -> list[tuple[Any, Any]]:
    """`<remap from to/>` entities as (from, to) substitution pairs."""
    remappings = []
    for remap in nested(entity, 'remap'):
        remappings.append((parser.parse_substitution(remap.get_attr('from')),
                           parser.parse_substitution(remap.get_attr('to'))))
        remap.assert_entity_completely_parsed()
    return remappings


def parse_node(entity: Entity, parser: Any) -> Parsed:
    """<node pkg exec name namespace args ros_args exec_name ...><param/><remap/><env/></node>."""
    kwargs = parse_process(entity, parser)  # 'name' is the node name for Node
    kwargs['executable'] = parser.parse_substitution(entity.get_attr('exec'))
    for attribute, key in (('pkg', 'package'), ('namespace', 'namespace'),
                           ('exec_name', 'exec_name')):
        text = entity.get_attr(attribute, optional=True)
        if text is not None:
            kwargs[key] = parser.parse_substitution(text)
    if kwargs.get('namespace') is not None and entity.get_attr('namespace') == '':
        # Jazzy starts a node given namespace="" in the root namespace (`__ns:=/`, golden 35).
        kwargs['namespace'] = parser.parse_substitution('/')
    for attribute, key in (('args', 'arguments'), ('ros_args', 'ros_arguments')):
        text = entity.get_attr(attribute, optional=True)
        if text is not None:
            kwargs[key] = parse_command(text, parser)
    params = nested(entity, 'param')
    if params:
        kwargs['parameters'] = parse_parameters(params, parser)
    remappings = parse_remappings(entity, parser)
    if remappings:
        kwargs['remappings'] = remappings
    return Node, kwargs


def parse_push_ros_namespace(entity: Entity, parser: Any) -> Parsed:
    """<push_ros_namespace namespace/>."""
    return PushRosNamespace, {
        'namespace': parser.parse_substitution(entity.get_attr('namespace')),
        **parse_condition(entity, parser)}


def parse_set_parameter(entity: Entity, parser: Any) -> Parsed:
    """<set_parameter name value/>: the value is typed as YAML when applied."""
    return SetParameter, {
        'name': parser.parse_substitution(entity.get_attr('name')),
        'value': parser.parse_substitution(entity.get_attr('value')),
        **parse_condition(entity, parser)}


def parse_set_remap(entity: Entity, parser: Any) -> Parsed:
    """<set_remap from to/>."""
    return SetRemap, {'src': parser.parse_substitution(entity.get_attr('from')),
                      'dst': parser.parse_substitution(entity.get_attr('to')),
                      **parse_condition(entity, parser)}


def _package_substitution(name: str, cls: type) -> Any:
    def parse(args: list[list[Any]]) -> Parsed:
        check_count(name, args, 1, 1)
        return cls, {'package': args[0]}
    return parse


def _exec_in_pkg(args: list[list[Any]]) -> Parsed:
    check_count('exec-in-pkg', args, 2, 2)
    return ExecutableInPackage, {'executable': args[0], 'package': args[1]}


ACTION_PARSE_METHODS = {
    'node': parse_node,
    'push_ros_namespace': parse_push_ros_namespace,
    'push-ros-namespace': parse_push_ros_namespace,
    'set_parameter': parse_set_parameter,
    'set_remap': parse_set_remap,
}

SUBSTITUTION_PARSE_METHODS = {
    'find-pkg-share': _package_substitution('find-pkg-share', FindPackageShare),
    'find-pkg-prefix': _package_substitution('find-pkg-prefix', FindPackagePrefix),
    'exec-in-pkg': _exec_in_pkg,
}

for _name, _method in ACTION_PARSE_METHODS.items():
    register_action_parse_method(_name, _method)
for _name, _method in SUBSTITUTION_PARSE_METHODS.items():
    register_substitution_parse_method(_name, _method)
