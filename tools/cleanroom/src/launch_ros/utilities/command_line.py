"""Assembly of a node's command line from already-substituted values.

The order is Jazzy's (conformance goldens 01, 06, 07, 12, 17):

    exe ARGS [--ros-args ROS_ARGS] --ros-args [-r __node:=NAME] [-r __ns:=NS]
        GLOBAL_PARAMS NODE_PARAMS GLOBAL_REMAPS NODE_REMAPS

where parameters are `-p name:=value` or `--params-file PATH` in the
order they were given.
"""
from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from .parameter_values import format_parameter_argument


@dataclass(frozen=True)
class ParamFileArg:
    """A `--params-file PATH` entry."""

    path: str


@dataclass(frozen=True)
class ParamArg:
    """A single `-p NAME:=VALUE` entry; `value` is already typed."""

    name: str
    value: Any


ParameterArgument = ParamFileArg | ParamArg


def parameter_arguments(entries: Iterable[ParameterArgument]) -> list[str]:
    """argv fragments for parameters, keeping their order."""
    argv: list[str] = []
    for entry in entries:
        if isinstance(entry, ParamFileArg):
            argv += ['--params-file', entry.path]
        else:
            argv += ['-p', format_parameter_argument(entry.name, entry.value)]
    return argv


def remap_arguments(rules: Iterable[tuple[str, str]]) -> list[str]:
    return [arg for src, dst in rules for arg in ('-r', f'{src}:={dst}')]


def global_parameter_entries(global_params: Iterable[Any]) -> list[ParameterArgument]:
    """Translate the `global_params` launch configuration into entries.

    SetParameter stores `(name, value)` tuples, SetParametersFromFile
    stores paths; see ARCHITECTURE.md.
    """
    entries: list[ParameterArgument] = []
    for item in global_params:
        if isinstance(item, tuple):
            entries.append(ParamArg(item[0], item[1]))
        else:
            entries.append(ParamFileArg(str(item)))
    return entries


def ros_specific_arguments(*, name: str | None = None, namespace: str | None = None,
                           parameters: Sequence[ParameterArgument] = (),
                           remappings: Sequence[tuple[str, str]] = ()) -> list[str]:
    """Everything after the final `--ros-args`; `parameters`/`remappings` already merged."""
    argv = ['--ros-args']
    if name:
        argv += ['-r', '__node:=' + name]
    if namespace:
        argv += ['-r', '__ns:=' + namespace]
    argv += parameter_arguments(parameters)
    argv += remap_arguments(remappings)
    return argv


def node_command_line(executable: str, *, arguments: Sequence[str] = (),
                      ros_arguments: Sequence[str] = (), name: str | None = None,
                      namespace: str | None = None,
                      parameters: Sequence[ParameterArgument] = (),
                      remappings: Sequence[tuple[str, str]] = ()) -> list[str]:
    """The full argv of a node (used by tests; Node itself builds it piecewise)."""
    argv = [executable, *arguments]
    if ros_arguments:
        argv += ['--ros-args', *ros_arguments]
    return argv + ros_specific_arguments(name=name, namespace=namespace,
                                         parameters=parameters, remappings=remappings)
