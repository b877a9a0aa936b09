"""The tags of `launch` (arg, let, group, include, executable, timer, log, ...).

Each parse method returns `(constructor, kwargs)` so that subclasses (Node in
launch_ros) can extend the keyword arguments of the base tag.
"""
from __future__ import annotations

from typing import Any

from ..action import Action
from ..actions import (
    AppendEnvironmentVariable,
    DeclareLaunchArgument,
    ExecuteProcess,
    GroupAction,
    IncludeLaunchDescription,
    LogInfo,
    SetEnvironmentVariable,
    SetLaunchConfiguration,
    Shutdown,
    TimerAction,
    UnsetEnvironmentVariable,
    UnsetLaunchConfiguration,
)
from .command_line import split_command_line
from .entity import Entity, EntityListType
from .expose import register_action_parse_method

Parsed = tuple[type, dict[str, Any]]


def parse_condition(entity: Entity, parser: Any) -> dict[str, Any]:
    """The `if` / `unless` attributes every action accepts, as a `condition` kwarg
    (Action.parse's)."""
    return Action.parse(entity, parser)[1]


def optional_substitution(entity: Entity, name: str, parser: Any) -> list[Any] | None:
    """Attribute `name` parsed for substitutions, or None when absent."""
    text = entity.get_attr(name, optional=True)
    return None if text is None else parser.parse_substitution(text)


def nested(entity: Entity, name: str) -> list[Entity]:
    """The nested entities called `name` (XML child tags, YAML list under the key)."""
    return entity.get_attr(name, data_type=EntityListType, optional=True) or []


def parse_name_value_pairs(entity: Entity, name: str, parser: Any) -> list[tuple[Any, Any]]:
    """`<env name=.. value=..>`-like nested entities as (name, value) substitution pairs."""
    pairs = []
    for item in nested(entity, name):
        pairs.append((parser.parse_substitution(item.get_attr('name')),
                      parser.parse_substitution(item.get_attr('value'))))
        item.assert_entity_completely_parsed()
    return pairs


def parse_command(text: str, parser: Any) -> list[list[Any]]:
    """A command line attribute as a list of arguments, each a list of substitutions."""
    return [parser.parse_substitution(token) for token in split_command_line(text)]


def parse_bool_or_substitution(entity: Entity, name: str, parser: Any) -> Any:
    """A boolean attribute that may also be a substitution; None when absent."""
    value = entity.get_attr(name, data_type=bool, optional=True)
    if isinstance(value, str):
        return parser.parse_substitution(value)
    return value


def parse_process(entity: Entity, parser: Any) -> dict[str, Any]:
    """Keyword arguments of ExecuteProcess common to `executable` and `node`."""
    kwargs = parse_condition(entity, parser)
    for attribute, key in (('cwd', 'cwd'), ('name', 'name'), ('launch-prefix', 'prefix'),
                           ('output', 'output'), ('sigterm_timeout', 'sigterm_timeout'),
                           ('sigkill_timeout', 'sigkill_timeout')):
        value = optional_substitution(entity, attribute, parser)
        if value is not None:
            kwargs[key] = value
    for attribute in ('shell', 'emulate_tty', 'respawn'):
        value = parse_bool_or_substitution(entity, attribute, parser)
        if value is not None:
            kwargs[attribute] = value
    respawn_delay = entity.get_attr('respawn_delay', data_type=float, optional=True,
                                    can_be_str=False)
    if respawn_delay is not None:
        kwargs['respawn_delay'] = respawn_delay
    env = parse_name_value_pairs(entity, 'env', parser)
    if env:
        kwargs['additional_env'] = env
    return kwargs


def parse_arg(entity: Entity, parser: Any) -> Parsed:
    """<arg name default description><choice value/></arg>."""
    kwargs: dict[str, Any] = {'name': entity.get_attr('name')}
    default = entity.get_attr('default', optional=True)
    if default is not None:
        kwargs['default_value'] = parser.parse_substitution(default)
    description = entity.get_attr('description', optional=True)
    if description is not None:
        kwargs['description'] = description
    choices = nested(entity, 'choice')
    if choices:
        kwargs['choices'] = [choice.get_attr('value') for choice in choices]
        for choice in choices:
            choice.assert_entity_completely_parsed()
    kwargs.update(parse_condition(entity, parser))
    return DeclareLaunchArgument, kwargs


def parse_let(entity: Entity, parser: Any) -> Parsed:
    """<let name value/>: set a launch configuration."""
    return SetLaunchConfiguration, {
        'name': parser.parse_substitution(entity.get_attr('name')),
        'value': parser.parse_substitution(entity.get_attr('value')),
        **parse_condition(entity, parser)}


def parse_group(entity: Entity, parser: Any) -> Parsed:
    """<group scoped forwarding>children</group>."""
    kwargs = parse_condition(entity, parser)
    for attribute in ('scoped', 'forwarding'):
        value = entity.get_attr(attribute, data_type=bool, optional=True)
        if value is not None:
            kwargs[attribute] = value
    kwargs['actions'] = [parser.parse_action(child) for child in entity.children]
    return GroupAction, kwargs


def parse_include(entity: Entity, parser: Any) -> Parsed:
    """<include file><arg name value/></include>."""
    # A path (not a source object) makes IncludeLaunchDescription load it with
    # AnyLaunchDescriptionSource, without this module importing the sources (a cycle).
    path = parser.parse_substitution(entity.get_attr('file'))
    arguments = parse_name_value_pairs(entity, 'arg', parser)
    return IncludeLaunchDescription, {'launch_description_source': path,
                                      'launch_arguments': arguments,
                                      **parse_condition(entity, parser)}


def parse_executable(entity: Entity, parser: Any) -> Parsed:
    """<executable cmd args cwd name shell output ...><env/></executable>."""
    cmd = parse_command(entity.get_attr('cmd'), parser)
    args = entity.get_attr('args', optional=True)
    if args is not None:
        cmd += parse_command(args, parser)
    return ExecuteProcess, {'cmd': cmd, **parse_process(entity, parser)}


def parse_timer(entity: Entity, parser: Any) -> Parsed:
    """<timer period>children</timer>; a period that is no number fails the load."""
    period = entity.get_attr('period', data_type=None)
    if isinstance(period, str):
        period = parser.parse_substitution(period) if '$(' in period else float(period)
    return TimerAction, {'period': period,
                         'actions': [parser.parse_action(child) for child in entity.children],
                         **parse_condition(entity, parser)}


def parse_log(entity: Entity, parser: Any) -> Parsed:
    """<log message/>."""
    return LogInfo, {'msg': parser.parse_substitution(entity.get_attr('message')),
                     **parse_condition(entity, parser)}


def parse_set_env(entity: Entity, parser: Any) -> Parsed:
    """<set_env name value/>."""
    return SetEnvironmentVariable, {
        'name': parser.parse_substitution(entity.get_attr('name')),
        'value': parser.parse_substitution(entity.get_attr('value')),
        **parse_condition(entity, parser)}


def parse_unset_env(entity: Entity, parser: Any) -> Parsed:
    """<unset_env name/>."""
    return UnsetEnvironmentVariable, {
        'name': parser.parse_substitution(entity.get_attr('name')),
        **parse_condition(entity, parser)}


def parse_append_env(entity: Entity, parser: Any) -> Parsed:
    """<append_env name value prepend separator/>."""
    kwargs = {'name': parser.parse_substitution(entity.get_attr('name')),
              'value': parser.parse_substitution(entity.get_attr('value')),
              **parse_condition(entity, parser)}
    prepend = parse_bool_or_substitution(entity, 'prepend', parser)
    if prepend is not None:
        kwargs['prepend'] = prepend
    separator = optional_substitution(entity, 'separator', parser)
    if separator is not None:
        kwargs['separator'] = separator
    return AppendEnvironmentVariable, kwargs


def parse_unset_configuration(entity: Entity, parser: Any) -> Parsed:
    """<unset name/>: remove a launch configuration."""
    return UnsetLaunchConfiguration, {
        'name': parser.parse_substitution(entity.get_attr('name')),
        **parse_condition(entity, parser)}


def parse_shutdown(entity: Entity, parser: Any) -> Parsed:
    """<shutdown reason/>."""
    kwargs = parse_condition(entity, parser)
    reason = entity.get_attr('reason', optional=True)
    if reason is not None:
        kwargs['reason'] = reason
    return Shutdown, kwargs


PARSE_METHODS = {
    'arg': parse_arg,
    'let': parse_let,
    'unset': parse_unset_configuration,
    'group': parse_group,
    'include': parse_include,
    'executable': parse_executable,
    'timer': parse_timer,
    'log': parse_log,
    'set_env': parse_set_env,
    'unset_env': parse_unset_env,
    'append_env': parse_append_env,
    'shutdown': parse_shutdown,
}

for _name, _method in PARSE_METHODS.items():
    register_action_parse_method(_name, _method)

__all__ = ['nested', 'parse_command', 'parse_condition', 'parse_name_value_pairs',
           'parse_process']
