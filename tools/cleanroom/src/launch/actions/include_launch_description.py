"""Include another launch description (usually a launch file)."""
from __future__ import annotations

import os
from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..action import Action
from ..launch_context import LaunchContext
from ..launch_description import LaunchDescription
from ..launch_description_entity import LaunchDescriptionEntity
from ..launch_description_source import LaunchDescriptionSource
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..some_substitutions_type import SomeSubstitutionsType

ArgumentPair = tuple[list[Substitution], list[Substitution]]


class IncludeLaunchDescription(Action):
    """Visit the launch description of `launch_description_source` here.

    `launch_arguments` become launch configurations *without* a scope of
    their own: as in ROS 2 Jazzy they stay set after the include (wrap the
    include in a GroupAction to scope them).  Declared arguments without a
    default that the include does not give are an error, reported before
    anything of the included file runs.
    """

    def __init__(self, launch_description_source: object, *,
                 launch_arguments: (Iterable[tuple[SomeSubstitutionsType, SomeSubstitutionsType]]
                                    | None) = None,
                 **kwargs: object) -> None:
        # late: launch_description_sources parse front-end files into actions (a cycle)
        from ..launch_description_sources import AnyLaunchDescriptionSource

        super().__init__(**kwargs)
        if isinstance(launch_description_source, LaunchDescription):
            launch_description_source = LaunchDescriptionSource(launch_description_source)
        elif not isinstance(launch_description_source, LaunchDescriptionSource):
            launch_description_source = AnyLaunchDescriptionSource(launch_description_source)
        self.__source = launch_description_source
        if isinstance(launch_arguments, dict):
            launch_arguments = launch_arguments.items()
        self.__launch_arguments: list[ArgumentPair] = [
            (normalize_to_list_of_substitutions(name), normalize_to_list_of_substitutions(value))
            for name, value in (launch_arguments or [])]

    @property
    def launch_description_source(self) -> LaunchDescriptionSource:
        """Where the description comes from."""
        return self.__source

    @property
    def launch_arguments(self) -> list[ArgumentPair]:
        """The (name, value) pairs given, as substitutions."""
        return self.__launch_arguments

    def describe(self) -> str:
        """Return a description."""
        return f"IncludeLaunchDescription('{self.__source.location}')"

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """The included description, when it can be loaded without a context."""
        description = self.__source.try_get_launch_description_without_context()
        return [description] if description is not None else []

    def _try_get_arguments_names_without_context(self) -> list[str]:
        names = []
        for name, _ in self.__launch_arguments:
            try:
                names.append(perform_substitutions(LaunchContext(), name))
            except Exception:  # noqa: BLE001 - best effort, for the missing-argument check
                pass
        return names

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        """Load the description, check and set the arguments, return it to be visited."""
        description = self.__source.get_launch_description(context)
        given = [(perform_substitutions(context, name), perform_substitutions(context, value))
                 for name, value in self.__launch_arguments]
        self.__check_required_arguments(description, [name for name, _ in given])
        for name, value in given:
            context.launch_configurations[name] = value
        location = self.__source.location
        local_values = {}
        if os.path.exists(location):
            location = os.path.abspath(location)
            local_values = {'current_launch_file_path': location,
                            'launch_file_path': location,
                            'current_launch_file_directory': os.path.dirname(location)}
        # Not popped afterwards: as in Jazzy, $(dirname) / ThisLaunchFileDir after an
        # include name the included file's folder (frontends golden 33_xml_include).
        context.extend_locals(local_values)
        return [description]

    @staticmethod
    def __check_required_arguments(description: LaunchDescription, given: list[str]) -> None:
        declared = description.get_launch_arguments_with_include_launch_description_actions()
        for argument, includes in declared:
            if argument._conditionally_included or argument.default_value is not None:
                continue
            names = list(given)
            for include in includes:
                names.extend(include._try_get_arguments_names_without_context())
            if argument.name not in names:
                raise RuntimeError(
                    f"Included launch description missing required argument '{argument.name}' "
                    f"(description: '{argument.description}'), given: [{', '.join(names)}]")
