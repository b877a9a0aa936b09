"""Work out what a launch file would start, without starting anything.

The walk does what a LaunchService does with the entities of a launch file,
in the same order, but only for entities whose visit has no effect outside
the LaunchContext (launch descriptions, includes, groups, launch arguments
and configurations).  Node actions are never visited: their constructor
arguments (see node_capture) are evaluated in the context as it is at that
point, together with the ROS state that PushROSNamespace, SetParameter,
SetParametersFromFile and SetRemap set before them.  That state is kept in
the context's launch configurations, so it is scoped exactly like launch
configurations are (a scoped GroupAction ends it).  Whatever only happens
while a launch runs (OpaqueFunction, event handlers, TimerAction, plain
processes) is listed as not checked statically.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import launch
import launch_ros.actions
import yaml
from launch.actions import (
    DeclareLaunchArgument,
    GroupAction,
    IncludeLaunchDescription,
    PopLaunchConfigurations,
    PushLaunchConfigurations,
    ResetLaunchConfigurations,
    SetLaunchConfiguration,
    UnsetLaunchConfiguration,
)
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions
from launch_ros.parameter_descriptions import Parameter
from launch_ros.utilities import (
    evaluate_parameters,
    make_namespace_absolute,
    normalize_parameters,
    normalize_remap_rules,
    prefix_namespace,
)

from speccheck.constructor_capture import ConstructorArguments, capturing_constructor_arguments
from speccheck.param_files import ParameterFileError, read_blocks

#: Launch configuration key of the ROS state of the current scope (our own).
ROS_STATE_KEY = 'speccheck.ros_state'

#: Entities whose visit only changes the LaunchContext: safe to visit.
SAFE_TO_VISIT = (launch.LaunchDescription, IncludeLaunchDescription, GroupAction,
                 DeclareLaunchArgument, SetLaunchConfiguration, UnsetLaunchConfiguration,
                 PushLaunchConfigurations, PopLaunchConfigurations, ResetLaunchConfigurations)

#: Scope markers a GroupAction adds; they only touch the context.
SAFE_TO_VISIT += tuple(getattr(launch.actions, name) for name in (
    'PushEnvironment', 'PopEnvironment', 'ResetEnvironment') if hasattr(launch.actions, name))

#: Entities that do nothing a spec is about; skipped without a note.
IRRELEVANT = tuple(getattr(launch.actions, name) for name in (
    'LogInfo', 'SetEnvironmentVariable', 'UnsetEnvironmentVariable',
    'AppendEnvironmentVariable') if hasattr(launch.actions, name))


@dataclass(frozen=True)
class ParameterSetting:
    """One parameter value a node would get, and where it comes from."""

    name: str
    value: Any
    origin: str
    #: True when aimed at this node (its own dict, or a file key naming it);
    #: False for SetParameter and wildcard file keys, which every node gets.
    targeted: bool


@dataclass(frozen=True)
class RosState:
    namespace: str = ''
    parameters: tuple = ()   # ParameterSetting or ('file', path) entries, in order
    remaps: tuple[tuple[str, str], ...] = ()


@dataclass
class PlannedNode:
    """A node the launch file would start, after substitutions."""

    package: str
    executable: str
    name: str | None          # None: the program chooses its own name
    namespace: str
    remaps: list[tuple[str, str]]
    settings: list[ParameterSetting]
    launch_file: str
    notes: list[str] = field(default_factory=list)

    @property
    def full_name(self) -> str | None:
        if self.name is None:
            return None
        return self.namespace.rstrip('/') + '/' + self.name

    @property
    def label(self) -> str:
        return self.full_name or f'{self.package}/{self.executable} (in {self.namespace})'

    def parameters(self) -> dict[str, ParameterSetting]:
        """Final setting of each parameter: later sources win, as in ROS 2."""
        final: dict[str, ParameterSetting] = {}
        for setting in self.settings:
            final[setting.name] = setting
        return final


@dataclass(frozen=True)
class DeclaredArgument:
    name: str
    default: str | None
    choices: tuple[str, ...] | None
    launch_file: str


@dataclass
class StaticSystem:
    """Everything the walk found."""

    launch_file: str
    given: dict[str, str]
    nodes: list[PlannedNode] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)           # nodes whose condition is false
    top_arguments: list[DeclaredArgument] = field(default_factory=list)
    all_arguments: list[DeclaredArgument] = field(default_factory=list)
    not_checked: list[str] = field(default_factory=list)
    #: (kind, launch file name) of each part that may start nodes the walk cannot see
    hidden: list[tuple[str, str]] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)
    error: str | None = None


def walk_launch_file(path: str | Path, arguments: dict[str, str] | None = None) -> StaticSystem:
    """What `ros2 launch PATH name:=value ...` would start, found without starting it."""
    given = dict(arguments or {})
    system = StaticSystem(str(path), given)
    context = launch.LaunchContext()
    root = IncludeLaunchDescription(AnyLaunchDescriptionSource(str(path)),
                                    launch_arguments=list(given.items()))
    with capturing_constructor_arguments(_RECORDED_CLASSES) as recorded:
        walker = _Walker(system, context, recorded)
        try:
            walker.visit(root, str(path))
        except Exception as error:  # the launch file itself fails: report it as launch would
            system.error = str(error) or type(error).__name__
    return system


class _Walker:
    def __init__(self, system: StaticSystem, context: launch.LaunchContext,
                 recorded: ConstructorArguments) -> None:
        self.system = system
        self.context = context
        self.recorded = recorded
        self.root_seen = False

    # -- dispatch --------------------------------------------------------
    def visit(self, entity: Any, launch_file: str, helpers_allowed: bool = False) -> None:
        """Handle one entity; `helpers_allowed` when an include or group returned it."""
        internal_helper = helpers_allowed and _is_internal_helper(entity)
        if isinstance(entity, launch_ros.actions.Node):
            if self._condition_holds(entity):
                self._plan_node(entity, launch_file)
            else:
                self.system.skipped.append(self._describe_node(entity))
            return
        if isinstance(entity, _ROS_STATE_ACTIONS):
            if self._condition_holds(entity):
                self._apply_ros_state(entity, launch_file)
            return
        if isinstance(entity, launch.LaunchDescription):
            self._note_arguments(entity, launch_file)
        if isinstance(entity, DeclareLaunchArgument):
            self._record_declaration(entity, launch_file)
        if isinstance(entity, SAFE_TO_VISIT) or internal_helper:
            sub_entities = entity.visit(self.context) or ()
            if isinstance(entity, IncludeLaunchDescription):
                launch_file = self._include_location(entity, launch_file)
            helpers_allowed = isinstance(entity, (IncludeLaunchDescription, GroupAction))
            for sub_entity in sub_entities:
                self.visit(sub_entity, launch_file, helpers_allowed)
            return
        if isinstance(entity, IRRELEVANT) or not self._condition_holds(entity):
            return
        kind, where = _kind(entity), Path(launch_file).name
        self.system.not_checked.append(f'{kind} in {where}: {_what_it_hides(entity)}')
        if kind in MAY_START_NODES or isinstance(entity, launch.actions.ExecuteProcess):
            self.system.hidden.append((kind, where))

    def _condition_holds(self, entity: Any) -> bool:
        condition = getattr(entity, 'condition', None)
        return condition is None or bool(condition.evaluate(self.context))

    def _include_location(self, include: IncludeLaunchDescription, current: str) -> str:
        try:
            return str(include.launch_description_source.location)
        except Exception:  # noqa: BLE001 - a location is only a label here
            return current

    # -- launch arguments ------------------------------------------------
    def _note_arguments(self, description: launch.LaunchDescription, launch_file: str) -> None:
        if self.root_seen:
            return
        self.root_seen = True
        self.system.top_arguments = [self._declared(argument, launch_file)
                                     for argument in description.get_launch_arguments()]

    def _record_declaration(self, argument: DeclareLaunchArgument, launch_file: str) -> None:
        self.system.all_arguments.append(self._declared(argument, launch_file))

    def _declared(self, argument: DeclareLaunchArgument, launch_file: str) -> DeclaredArgument:
        default = argument.default_value
        if default is not None:
            try:
                default = perform_substitutions(self.context, default)
            except Exception:  # noqa: BLE001 - depends on something not set yet
                default = ''.join(sub.describe() for sub in default)
        choices = argument.choices
        return DeclaredArgument(argument.name, default,
                                None if choices is None else tuple(choices), launch_file)

    # -- ROS state: namespace, global parameters, global remaps ----------
    def _state(self) -> RosState:
        return self.context.launch_configurations.get(ROS_STATE_KEY) or RosState()

    def _apply_ros_state(self, action: Any, launch_file: str) -> None:
        state = self._state()
        if isinstance(action, launch_ros.actions.PushROSNamespace):
            pushed = self._text(action.namespace)
            state = replace(state, namespace=prefix_namespace(state.namespace or None, pushed)
                            if pushed else state.namespace)
        elif isinstance(action, launch_ros.actions.SetRemap):
            state = replace(state, remaps=(*state.remaps,
                                           (self._text(action.src), self._text(action.dst))))
        elif isinstance(action, launch_ros.actions.SetParametersFromFile):
            given = self.recorded.get(action) or {}
            if 'filename' not in given:
                self.system.not_checked.append(
                    f'SetParametersFromFile in {Path(launch_file).name}: its file')
                return
            if given.get('allow_substs'):
                self.system.not_checked.append(
                    f'SetParametersFromFile in {Path(launch_file).name}: substitutions inside '
                    'the file (allow_substs) are not expanded by the static check')
            state = replace(state, parameters=(*state.parameters,
                                               ('file', self._text(given['filename']))))
        else:  # SetParameter(name, value), SetUseSimTime(value)
            if isinstance(action, launch_ros.actions.SetParameter):
                name, value = self._text(action.name), action.value
            else:
                name, value = 'use_sim_time', (self.recorded.get(action) or {}).get('value')
            values = evaluate_parameters(self.context, normalize_parameters([{name: value}]))
            state = replace(state, parameters=(*state.parameters, *(
                ParameterSetting(key, evaluated, f'{type(action).__name__} in '
                                 f'{Path(launch_file).name}', False)
                for item in values if isinstance(item, dict)
                for key, evaluated in item.items())))
        self.context.launch_configurations[ROS_STATE_KEY] = state

    # -- nodes -----------------------------------------------------------
    def _text(self, value: Any) -> str:
        if value is None:
            return ''
        return perform_substitutions(self.context, normalize_to_list_of_substitutions(value))

    def _label(self, value: Any) -> str:
        try:
            return self._text(value)
        except Exception:  # noqa: BLE001 - only a label
            return _described(value)

    def _describe_node(self, node: Any) -> str:
        kwargs = self.recorded.get(node) or {}
        name = kwargs.get('name')
        label = self._label(name) if name is not None else None
        package = self._label(kwargs.get('package'))
        executable = self._label(kwargs.get('executable'))
        return f'{label or "(unnamed)"} ({package}/{executable})'

    def _plan_node(self, node: Any, launch_file: str) -> None:
        kwargs = self.recorded.get(node)
        if kwargs is None:
            self.system.not_checked.append(
                f'Node in {Path(launch_file).name}: created before the check started')
            return
        state = self._state()
        own_namespace = self._text(kwargs.get('namespace'))
        namespace = make_namespace_absolute(
            prefix_namespace(state.namespace or None, own_namespace) if own_namespace
            else (state.namespace or '/'))
        name = self._text(kwargs.get('name')) or None
        planned = PlannedNode(self._text(kwargs.get('package')),
                              self._text(kwargs.get('executable')), name, namespace,
                              [], [], launch_file)
        # In the order the node's command line gets them (ros_arguments come
        # first): for parameters the last value wins, for remaps the first rule.
        self._ros_arguments(planned, kwargs.get('ros_arguments'))
        if name is not None:
            planned.name = name
        planned.remaps += state.remaps
        for rule in normalize_remap_rules(kwargs.get('remappings') or []):
            planned.remaps.append((self._text(rule[0]), self._text(rule[1])))
        for entry in state.parameters:
            self._add_parameters(planned, entry, origin_prefix='SetParametersFromFile ')
        own = kwargs.get('parameters')
        if own:
            for item in evaluate_parameters(self.context, normalize_parameters(own)):
                self._add_parameters(planned, item, origin_prefix='')
        if kwargs.get('composable_node_descriptions'):
            planned.notes.append('the composable nodes loaded into this container are not '
                                 'checked statically')
        self.system.nodes.append(planned)

    def _ros_arguments(self, planned: PlannedNode, ros_arguments: Any) -> None:
        if not ros_arguments:
            return
        words = [self._text(word) for word in ros_arguments]
        for flag, value in zip(words, words[1:], strict=False):
            if flag in ('-r', '--remap') and ':=' in value:
                source, target = value.split(':=', 1)
                if source == '__node':
                    planned.name = target
                elif source == '__ns':
                    planned.namespace = make_namespace_absolute(target)
                else:
                    planned.remaps.append((source, target))
            elif flag in ('-p', '--param') and ':=' in value:
                key, text = value.split(':=', 1)
                planned.settings.append(ParameterSetting(
                    key, yaml.safe_load(text), 'ros_arguments', True))

    def _add_parameters(self, planned: PlannedNode, item: Any, origin_prefix: str) -> None:
        if isinstance(item, dict):
            planned.settings += [ParameterSetting(name, value, "the Node's parameters", True)
                                 for name, value in item.items()]
        elif isinstance(item, ParameterSetting):
            planned.settings.append(item)
        elif isinstance(item, Parameter):  # evaluate_parameters hands a Parameter on as is
            name, value = item.evaluate(self.context)
            planned.settings.append(ParameterSetting(name, value, "the Node's parameters", True))
        elif isinstance(item, tuple) and item and item[0] == 'file':
            self._add_file(planned, item[1], origin_prefix)
        elif isinstance(item, (str, Path)):
            self._add_file(planned, str(item), '')
        else:
            planned.notes.append(f'a parameter entry of type {type(item).__name__} '
                                 '(not checked statically)')

    def _add_file(self, planned: PlannedNode, path: str, origin_prefix: str) -> None:
        try:
            blocks = read_blocks(path)
        except ParameterFileError as error:
            self.system.problems.append(f'{planned.label}: {error}')
            return
        for block in blocks:
            origin = f'{origin_prefix}{Path(path).name} key {block.pattern}'
            if planned.full_name is not None:
                if block.matches(planned.full_name):
                    planned.settings += [ParameterSetting(n, v, origin, not block.is_wildcard)
                                         for n, v in block.parameters.items()]
            elif block.pattern in ('/**', '/**/*'):
                planned.settings += [ParameterSetting(n, v, origin, False)
                                     for n, v in block.parameters.items()]
            else:
                planned.notes.append(f'{Path(path).name} key {block.pattern}: applies only if '
                                     'the program names its node so (not checked statically)')


_ROS_STATE_ACTIONS = tuple(getattr(launch_ros.actions, name) for name in (
    'PushROSNamespace', 'SetParameter', 'SetParametersFromFile', 'SetRemap', 'SetUseSimTime')
    if hasattr(launch_ros.actions, name))

#: Actions whose constructor arguments the walk needs (no public getter has them).
_RECORDED_CLASSES = tuple(getattr(launch_ros.actions, name) for name in (
    'Node', 'SetParametersFromFile', 'SetUseSimTime') if hasattr(launch_ros.actions, name))


_PUBLIC_ACTIONS = {value for module in (launch.actions, launch_ros.actions)
                   for value in vars(module).values() if isinstance(value, type)}


def _is_internal_helper(entity: Any) -> bool:
    """An entity the launch implementation itself adds to an include or a group
    (bookkeeping such as scope markers), as opposed to a user's action: its
    class belongs to launch / launch_ros but is not one of their public actions."""
    kind = type(entity)
    return kind.__module__.split('.')[0] in ('launch', 'launch_ros') \
        and kind not in _PUBLIC_ACTIONS


def _kind(entity: Any) -> str:
    return type(entity).__name__


def _described(value: Any) -> str:
    if value is None:
        return '?'
    try:
        return ''.join(sub.describe() if hasattr(sub, 'describe') else str(sub)
                       for sub in normalize_to_list_of_substitutions(value))
    except Exception:  # noqa: BLE001 - only a label
        return str(value)


#: Actions whose effect the walk cannot see and which may start nodes (a process may be one).
MAY_START_NODES = ('OpaqueFunction', 'OpaqueCoroutine', 'RegisterEventHandler', 'TimerAction')


def _what_it_hides(entity: Any) -> str:
    kind = _kind(entity)
    if kind in ('OpaqueFunction', 'OpaqueCoroutine'):
        return 'what its function does is only known when it runs; not checked statically'
    if kind in ('RegisterEventHandler', 'UnregisterEventHandler'):
        return 'the actions of the event handler run on events; not checked statically'
    if kind == 'TimerAction':
        return 'the actions it starts after its period are not checked statically'
    if isinstance(entity, launch.actions.ExecuteProcess):
        return 'a process that is not a ROS node action; not checked statically'
    return 'not checked statically'
