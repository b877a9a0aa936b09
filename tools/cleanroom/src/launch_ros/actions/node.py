"""The Node action: an ExecuteProcess whose command line carries ROS arguments.

Everything ROS-specific (name, namespace, parameters, remappings, plus the
global parameters and remappings set by SetParameter / SetRemap in scope)
is substituted when the action executes and appended to `self.cmd` before
`ExecuteProcess.execute` expands and starts it (ARCHITECTURE.md contract).
"""
from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from typing import Any

from launch import LaunchContext
from launch.actions import ExecuteProcess
from launch.logging import get_logger
from launch.substitutions import LocalSubstitution
from launch.utilities import normalize_to_list_of_substitutions

from .. import parameter_descriptions as descriptions
from ..substitutions import ExecutableInPackage
from ..utilities.command_line import (
    ParamArg,
    ParameterArgument,
    ParamFileArg,
    global_parameter_entries,
    ros_specific_arguments,
)
from ..utilities.evaluate_parameters import evaluate_parameters
from ..utilities.namespace_utils import full_node_namespace, fully_qualified_name
from ..utilities.normalize_parameters import normalize_parameters
from ..utilities.normalize_remap_rule import normalize_remap_rules
from ..utilities.param_files import write_parameters_file
from ..utilities.ros_state import global_params, global_remaps, pushed_namespace
from ..utilities.substitution_values import perform_text
from ..utilities.track_node_names import add_node_name

_logger_name = 'launch_ros.actions.node'


class Node(ExecuteProcess):
    """Start a ROS node from a package's libexec directory (or an executable on PATH)."""

    UNSPECIFIED_NODE_NAME = '<node_name_unspecified>'
    UNSPECIFIED_NODE_NAMESPACE = '<node_namespace_unspecified>'

    def __init__(self, *, executable: Any, package: Any = None, name: Any = None,
                 namespace: Any = None, exec_name: Any = None,
                 parameters: Sequence[Any] | None = None,
                 remappings: Iterable[Any] | None = None,
                 ros_arguments: Iterable[Any] | None = None,
                 arguments: Iterable[Any] | None = None, **kwargs: Any) -> None:
        if package is not None:
            cmd: list[Any] = [ExecutableInPackage(executable=executable, package=package)]
        else:
            cmd = [executable]
        cmd += list(arguments or [])
        ros_arguments = list(ros_arguments or [])
        if ros_arguments:
            cmd += ['--ros-args', *ros_arguments]
        super().__init__(cmd=cmd, name=exec_name, **kwargs)
        self.__base_cmd = list(self.cmd)
        # What `ros2 launch -p` shows before execution (observed on Jazzy): a bare
        # '--ros-args' always (a second one after ros_arguments), the name a placeholder.
        self.__described_name_args = ['--ros-args'] + ([] if name is None else [
            '-r', LocalSubstitution("ros_specific_arguments['name']", description='node name')])
        self.__package = package
        self.__executable = executable
        self.__node_name = None if name is None else normalize_to_list_of_substitutions(name)
        self.__node_namespace = (None if namespace is None
                                 else normalize_to_list_of_substitutions(namespace))
        self.__parameters = [] if parameters is None else normalize_parameters(parameters)
        # A generator in Jazzy; the Node checks every rule right away.
        self.__remappings = [] if remappings is None else list(normalize_remap_rules(remappings))
        self.__ros_arguments = ros_arguments
        self.__expanded_node_name = self.UNSPECIFIED_NODE_NAME
        self.__expanded_node_namespace = self.UNSPECIFIED_NODE_NAMESPACE
        self.__final_node_name: str | None = None
        self.__expanded_remappings: list[tuple[str, str]] | None = None
        self.__logger = get_logger(_logger_name)
        # Named, as given, in the error Jazzy logs when name or namespace fail to expand.
        self.__given_identity = (f'package={package}, executable={executable}, '
                                 f'name={name}, namespace={namespace}')

    # -- Jazzy's read-only properties -------------------------------------------------
    @property
    def node_package(self) -> Any:
        return self.__package

    @property
    def node_executable(self) -> Any:
        return self.__executable

    @property
    def node_name(self) -> str:
        """Fully qualified name once executed ('/ns/name'), else UNSPECIFIED_NODE_NAME."""
        return self.__final_node_name or self.UNSPECIFIED_NODE_NAME

    @property
    def expanded_node_namespace(self) -> str:
        return self.__expanded_node_namespace

    @property
    def expanded_remapping_rules(self) -> list[tuple[str, str]] | None:
        return self.__expanded_remappings

    @property
    def ros_arguments(self) -> list[Any]:
        return list(self.__ros_arguments)

    def is_node_name_fully_specified(self) -> bool:
        return (self.__expanded_node_name != self.UNSPECIFIED_NODE_NAME
                and self.__expanded_node_namespace != self.UNSPECIFIED_NODE_NAMESPACE)

    # -- execution --------------------------------------------------------------------
    def _expand_name_and_namespace(self, context: LaunchContext) -> tuple[str | None,
                                                                        str | None]:
        name = None if self.__node_name is None else perform_text(context, self.__node_name)
        own_ns = (None if self.__node_namespace is None
                  else perform_text(context, self.__node_namespace))
        namespace = full_node_namespace(pushed_namespace(context), own_ns)
        if name:
            self.__expanded_node_name = name
            self.__final_node_name = fully_qualified_name(namespace, name)
        if namespace:
            self.__expanded_node_namespace = namespace
        return name or None, namespace

    def _parameter_file_key(self, name: str | None, namespace: str | None) -> str:
        """Jazzy keys a parameter dict by '/ns/name' only when both are known (goldens 02, 17)."""
        if name and namespace:
            return fully_qualified_name(namespace, name)
        return '/**'

    def _parameter_arguments(self, context: LaunchContext, name: str | None,
                             namespace: str | None) -> list[ParameterArgument]:
        entries: list[ParameterArgument] = []
        global_entries = global_parameter_entries(global_params(context))
        evaluated = evaluate_parameters(context, self.__parameters)
        for entry in global_entries:
            if isinstance(entry, ParamFileArg):
                entry = self._checked_file(entry.path)
            if entry is not None:
                entries.append(entry)
        for item in evaluated:
            if isinstance(item, dict):
                path = write_parameters_file(self._parameter_file_key(name, namespace), item)
                entries.append(ParamFileArg(path))
            elif isinstance(item, descriptions.Parameter):
                entries.append(ParamArg(*item.evaluate(context)))
            else:
                checked = self._checked_file(str(item))
                if checked is not None:
                    entries.append(checked)
        return entries

    def _checked_file(self, path: str) -> ParamFileArg | None:
        """A missing parameter file only earns a warning in Jazzy (golden 25)."""
        if os.path.isfile(path):
            return ParamFileArg(path)
        self.__logger.warning(f'Parameter file path is not a file: {path}')
        return None

    def _ros_command_tail(self, context: LaunchContext) -> list[str]:
        try:
            name, namespace = self._expand_name_and_namespace(context)
        except Exception:
            # Jazzy logs which node failed before the launch reports the exception (errors/ 27).
            self.__logger.error('Error while expanding or validating node name or namespace '
                                f"for '{self.__given_identity}':")
            raise
        parameters = self._parameter_arguments(context, name, namespace)
        own_remaps = [(perform_text(context, src), perform_text(context, dst))
                      for src, dst in self.__remappings]
        self.__expanded_remappings = global_remaps(context) + own_remaps
        if self.__final_node_name:
            add_node_name(context, self.__final_node_name)
        return ros_specific_arguments(name=name, namespace=namespace, parameters=parameters,
                                      remappings=self.__expanded_remappings)

    def _described_cmd(self) -> list[Any]:
        """The command `ros2 launch -p` prints: the node name arguments are still placeholders."""
        return self.__base_cmd + [normalize_to_list_of_substitutions(arg)
                                  for arg in self.__described_name_args]

    def execute(self, context: LaunchContext) -> list[Any] | None:
        tail = self._ros_command_tail(context)
        self.cmd[:] = self.__base_cmd + [normalize_to_list_of_substitutions(arg) for arg in tail]
        return super().execute(context)
