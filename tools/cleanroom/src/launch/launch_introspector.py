"""Render a launch description as `ros2 launch --print` shows it, in Jazzy's format.

Everything below is observed Jazzy output, warts included: only processes,
LogInfo, EmitEvent and RegisterEventHandler are described; any other action
is `Action('<its str()>')` (groups, includes and timers are not expanded), any
other entity `Unknown entity('...')`.  A formatted entity is a block of lines
whose first is its own; the lines below are already prefixed, and the prefix
they get from the level above depends on where they are: at the top level
'│   ' (or '    ' on the very last line), inside a handler always '    '.
A line that is the last of its list gets '└── ', every other first line '├── ',
even that of the last entity when lines of its own follow it.
"""
from __future__ import annotations

from collections.abc import Iterable

from .action import Action
from .actions import EmitEvent, ExecuteProcess, LogInfo, RegisterEventHandler
from .event_handler import BaseEventHandler
from .launch_description import LaunchDescription
from .launch_description_entity import LaunchDescriptionEntity
from .substitution import Substitution

Block = list[str]


def _join(substitutions: Iterable[Substitution]) -> str:
    return ' + '.join(s.describe() for s in substitutions)


def _prefixed(blocks: list[Block], continuation: str) -> list[str]:
    lines = [(index == 0, line) for block in blocks for index, line in enumerate(block)]
    out = []
    for number, (first, line) in enumerate(lines):
        last = number == len(lines) - 1
        if first:
            out.append(('└── ' if last else '├── ') + line)
        else:
            out.append(('    ' if last else continuation) + line)
    return out


def _top_level(blocks: list[Block]) -> list[str]:
    return _prefixed(blocks, '│   ')


def _nested(blocks: list[Block]) -> list[str]:
    return _prefixed(blocks, '    ')


def _format_event_handler(event_handler: BaseEventHandler) -> Block:
    description, entities = event_handler.describe()
    return [description] + _nested(format_entities(entities))


def _format_process(process: ExecuteProcess) -> str:
    cmd = ', '.join(_join(part) for part in process._described_cmd())
    cwd = None if process.cwd is None else f"'{_join(process.cwd)}'"
    env = None if process.env is None else \
        '{' + ', '.join(f'{_join(key)}: {_join(value)}' for key, value in process.env) + '}'
    return f'ExecuteProcess(cmd=[{cmd}], cwd={cwd}, env={env}, shell={process.shell})'


def _format_action(action: Action) -> Block:
    if isinstance(action, ExecuteProcess):
        return [_format_process(action)]
    if isinstance(action, LogInfo):
        return [f'LogInfo({_join(action.msg)})']
    if isinstance(action, EmitEvent):
        return [f"EmitEvent(event='{action.event.name}')"]
    if isinstance(action, RegisterEventHandler):
        handler = action.event_handler
        return [f"RegisterEventHandler('{handler}'):"] + \
            _nested([_format_event_handler(handler)])
    return [f"Action('{action}')"]


def _format_entity(entity: LaunchDescriptionEntity) -> Block:
    if isinstance(entity, Action):
        return _format_action(entity)
    return [f"Unknown entity('{entity}')"]


def format_entities(entities: Iterable[LaunchDescriptionEntity]) -> list[Block]:
    """Return one block of lines per entity."""
    return [_format_entity(entity) for entity in entities]


def format_launch_description(launch_description: LaunchDescription) -> str:
    """Return the description's repr, then its entities as a tree."""
    lines = [object.__repr__(launch_description)]
    lines += _top_level(format_entities(launch_description.entities))
    return '\n'.join(lines)


class LaunchIntrospector:
    """Formats launch descriptions for humans."""

    def format_launch_description(self, launch_description: LaunchDescription) -> str:
        """Return the description as `ros2 launch -p` prints it."""
        return format_launch_description(launch_description)
