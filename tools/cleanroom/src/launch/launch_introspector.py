"""Render a launch description as a tree (what `ros2 launch --print` shows)."""
from __future__ import annotations

from .launch_description import LaunchDescription
from .launch_description_entity import LaunchDescriptionEntity


def _tree(entity: LaunchDescriptionEntity, prefix: str, out: list[str], depth: int) -> None:
    children: list[tuple] = [('', child) for child in entity.describe_sub_entities()]
    for condition, entities in entity.describe_conditional_sub_entities():
        children += [(f'[{condition}] ', child) for child in entities]
    if depth > 50:
        return
    for index, (label, child) in enumerate(children):
        last = index == len(children) - 1
        out.append(f"{prefix}{'└── ' if last else '├── '}{label}{child.describe()}")
        _tree(child, prefix + ('    ' if last else '│   '), out, depth + 1)


def format_entities(entities: list[LaunchDescriptionEntity]) -> str:
    """Return the tree of several entities."""
    return format_launch_description(LaunchDescription(entities))


def format_launch_description(launch_description: LaunchDescription) -> str:
    """Return the description as an indented tree, one entity per line."""
    out = [object.__repr__(launch_description)]  # Jazzy's first line: the object's repr
    _tree(launch_description, '', out, 0)
    return '\n'.join(out)


class LaunchIntrospector:
    """Formats launch descriptions for humans."""

    def format_launch_description(self, launch_description: LaunchDescription) -> str:
        """Return the description as an indented tree."""
        return format_launch_description(launch_description)
