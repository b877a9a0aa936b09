"""The extension points and extensions of the clean room's own `ros2`, as ros2cli names them.

Jazzy's ros2cli is assembled from Python entry points: every command is an
entry point of the group `ros2cli.command`, every sub-verb of a command one of
that command's group (`ros2topic.verb`, ...), and each such group is itself
announced as an extension point.  The clean room registers no entry points
(its `ros2` is one package); `ros2 extension_points` and `ros2 extensions`
list what it really has, derived at run time and put in ros2cli's shape:

* `ros2cli.command`: every command of `cli.COMMANDS` (those `ros2 -h` shows,
  the hidden ones and the alias `wtf`), described by its help text;
* one verb group per command whose module's `build_parser()` has sub-verbs,
  named and described as Jazzy's ros2cli packages name theirs (VERB_GROUPS,
  their words kept, e.g. component's and multicast's descriptions that name
  another command); its extensions are the sub-parsers with their help texts.

A command without sub-verbs (`launch`, `run`) therefore has no extension point,
and an alias's verbs are listed once, under the command it runs: in both, as
Jazzy lists its own.  Each entry is an importlib.metadata.EntryPoint whose
value points at the clean room's code that runs it.
"""
from __future__ import annotations

import argparse
import importlib
from importlib.metadata import EntryPoint

from ros2_cleanroom.cli import ALIASES, COMMANDS

#: The group that announces extension points.
EXTENSION_POINT_GROUP = 'ros2cli.extension_point'
#: The extension point of the commands, in Jazzy's words.
COMMAND_GROUP = ('ros2cli.command', "The extension point for 'command' extensions")
#: command -> (extension point of its verbs, its description), as Jazzy names them.
VERB_GROUPS = {
    'action': ('ros2action.verb', "The extension point for 'action' verb extensions"),
    'component': ('ros2component.verb', "The extension point for 'node' verb extensions"),
    'daemon': ('ros2cli.daemon.verb', "The extension point for 'daemon' verb extensions"),
    'doctor': ('ros2doctor.verb', "The extension point for 'doctor' verb extensions"),
    'interface': ('ros2interface.verb', "Extension point for 'interface' verb extensions"),
    'lifecycle': ('ros2lifecycle.verb', "The extension point for 'lifecycle' verb extensions"),
    'multicast': ('ros2multicast.verb', "The extension point for 'msg' verb extensions"),
    'node': ('ros2node.verb', "The extension point for 'node' verb extensions"),
    'param': ('ros2param.verb', "The extension point for 'param' verb extensions"),
    'pkg': ('ros2pkg.verb', "The extension point for 'pkg' verb extensions"),
    'service': ('ros2service.verb', "The extension point for 'service' verb extensions"),
    'topic': ('ros2topic.verb', "The extension point for 'topic' verb extensions"),
}

#: An extension (or extension point) and the one line ros2cli describes it by.
Entry = tuple[EntryPoint, str]


def _module(command: str) -> str:
    return 'ros2_cleanroom.verbs.' + ALIASES.get(command, command)


def _sub_verbs(command: str) -> list[tuple[str, argparse.ArgumentParser, str]]:
    """(name, parser, help text) of each sub-verb of `command`: none without sub-parsers."""
    build = getattr(importlib.import_module(_module(command)), 'build_parser', None)
    verbs = getattr(build(), 'verbs', None) if build is not None else None
    if verbs is None:  # not a verb_args.command_parser: no sub-verbs
        return []
    helps = {choice.dest: choice.help or '' for choice in verbs._choices_actions}
    return [(name, sub, helps.get(name, '')) for name, sub in verbs.choices.items()]


def _verb_commands() -> dict[str, list[tuple[str, argparse.ArgumentParser, str]]]:
    """The commands (not aliases) that have sub-verbs, with them."""
    found = {command: _sub_verbs(command) for command in sorted(COMMANDS)
             if command not in ALIASES}
    return {command: verbs for command, verbs in found.items() if verbs}


def extension_points() -> list[Entry]:
    """Every extension point, sorted by name."""
    points = [(EntryPoint(COMMAND_GROUP[0], 'ros2_cleanroom.cli:main', EXTENSION_POINT_GROUP),
               COMMAND_GROUP[1])]
    for command in _verb_commands():
        name, text = VERB_GROUPS[command]
        points.append((EntryPoint(name, f'{_module(command)}:build_parser',
                                  EXTENSION_POINT_GROUP), text))
    return sorted(points, key=lambda entry: entry[0].name)


def extensions() -> dict[str, list[Entry]]:
    """Extension point name -> its extensions sorted by name; the points sorted by name."""
    group = COMMAND_GROUP[0]
    found = {group: [(EntryPoint(command, f'{_module(command)}:main', group), text)
                     for command, text in sorted(COMMANDS.items())]}
    for command, verbs in _verb_commands().items():
        group = VERB_GROUPS[command][0]
        found[group] = sorted(
            ((EntryPoint(name, f'{_module(command)}:{sub.get_default("handler").__name__}',
                         group), text) for name, sub, text in verbs),
            key=lambda entry: entry[0].name)
    return dict(sorted(found.items()))


def verbose_details(entry_point: EntryPoint) -> str:
    """The module an extension lives in, read as ros2cli's `--verbose` reads it.

    ros2cli asks for `module_name`, an attribute of pkg_resources' entry points
    that importlib.metadata's lack: Jazzy's `--verbose` ends right after the
    first entry it lists with `AttributeError: 'EntryPoint' object has no
    attribute 'module_name'` (a traceback, exit code 1), and so does this.
    """
    return entry_point.module_name  # type: ignore[attr-defined]
