"""LaunchDescription: the list of entities a launch file returns."""
from __future__ import annotations

import warnings
from collections.abc import Iterable
from typing import TYPE_CHECKING

from .action import Action
from .launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from .actions.declare_launch_argument import DeclareLaunchArgument
    from .actions.include_launch_description import IncludeLaunchDescription
    from .launch_context import LaunchContext


class LaunchDescription(LaunchDescriptionEntity):
    """An ordered collection of entities; visiting it yields them in order."""

    def __init__(self, initial_entities: Iterable[LaunchDescriptionEntity] | None = None, *,
                 deprecated_reason: str | None = None) -> None:
        self.__entities = list(initial_entities) if initial_entities is not None else []
        self.__deprecated_reason = deprecated_reason

    @property
    def entities(self) -> list[LaunchDescriptionEntity]:
        """The entities, in order."""
        return self.__entities

    @property
    def deprecated(self) -> bool:
        """True when the description was marked deprecated."""
        return self.__deprecated_reason is not None

    @property
    def deprecated_reason(self) -> str | None:
        """Why the description is deprecated, if it is."""
        return self.__deprecated_reason

    def add_entity(self, entity: LaunchDescriptionEntity) -> None:
        """Append an entity."""
        self.__entities.append(entity)

    def add_action(self, action: Action) -> None:
        """Append an action."""
        self.add_entity(action)

    def describe(self) -> str:
        """Return e.g. 'LaunchDescription(4 entities)'."""
        return f'LaunchDescription({len(self.__entities)} entities)'

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """The entities."""
        return self.__entities

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Return the entities so the service visits them in order."""
        if self.__deprecated_reason is not None:
            where = context.get_locals_as_dict().get('current_launch_file_path')
            warnings.warn(f"launch file '{where or '<unknown>'}' is deprecated: "
                          f'{self.__deprecated_reason}', UserWarning, stacklevel=2)
        return self.__entities

    def get_launch_arguments(self, conditional_inclusion: bool = False
                             ) -> list[DeclareLaunchArgument]:
        """Return the DeclareLaunchArgument actions found in this description.

        Found by walking the entities and their (conditional) sub-entities;
        arguments under a condition get `_conditionally_included = True`.
        Duplicate names are reported once, first declaration wins.
        """
        return [arg for arg, _ in self.get_launch_arguments_with_include_launch_description_actions(
            conditional_inclusion)]

    def get_launch_arguments_with_include_launch_description_actions(
            self, conditional_inclusion: bool = False
    ) -> list[tuple[DeclareLaunchArgument, list[IncludeLaunchDescription]]]:
        """Like get_launch_arguments(), with the includes each argument was found through."""
        # late: actions build on LaunchDescription, so it cannot import them at module level
        from .actions.declare_launch_argument import DeclareLaunchArgument
        from .actions.include_launch_description import IncludeLaunchDescription

        found: list[tuple[DeclareLaunchArgument, list[IncludeLaunchDescription]]] = []
        names = set()

        def walk(entities: Iterable[LaunchDescriptionEntity], conditional: bool,
                 includes: list[IncludeLaunchDescription]) -> None:
            for entity in entities:
                if isinstance(entity, DeclareLaunchArgument):
                    if entity.name in names:
                        continue
                    names.add(entity.name)
                    entity._conditionally_included = conditional or \
                        entity.condition is not None
                    found.append((entity, list(includes)))
                    continue
                entity_conditional = conditional or \
                    (isinstance(entity, Action) and entity.condition is not None)
                sub_includes = includes + [entity] \
                    if isinstance(entity, IncludeLaunchDescription) else includes
                walk(entity.describe_sub_entities(), entity_conditional, sub_includes)
                for _, sub in entity.describe_conditional_sub_entities():
                    walk(sub, True, sub_includes)

        walk(self.__entities, conditional_inclusion, [])
        return found
