"""Declare a launch argument: a launch configuration users may set from outside."""
from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..action import Action
from ..logging import get_logger
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class DeclareLaunchArgument(Action):
    """Make sure launch configuration `name` is set, from outside or from `default_value`.

    Without a default the argument is required; with `choices` the value must
    be one of them.  `ros2 launch --show-args` lists these declarations.
    """

    def __init__(self, name: str, *, default_value: SomeSubstitutionsType | None = None,
                 description: str | None = None,
                 choices: Iterable[str] | None = None, **kwargs: object) -> None:
        super().__init__(**kwargs)
        if not isinstance(name, str):
            raise TypeError(f"DeclareLaunchArgument expected 'name' to be a str, "
                            f"got '{type(name)}'")
        self.__name = name
        self.__default_value = None if default_value is None \
            else normalize_to_list_of_substitutions(default_value)
        self.__choices = list(choices) if choices is not None else None
        if self.__choices is not None:
            if not self.__choices:
                raise RuntimeError('Provided choices arg is empty')
            if isinstance(default_value, str) and default_value not in self.__choices:
                raise RuntimeError(f'Provided default_value "{default_value}" is not in '
                                   f'provided choices "{self.__choices}".')
        if description is None:
            description = f'One of: {self.__choices}' if self.__choices is not None \
                else 'no description given'
        elif self.__choices is not None:
            # Jazzy appends the choices to a given description, even an empty one.
            description += f'. Valid choices are: {self.__choices}'
        self.__description = description
        # Set by LaunchDescription.get_launch_arguments(): declared under a condition.
        self._conditionally_included = False

    @property
    def name(self) -> str:
        """The argument name."""
        return self.__name

    @property
    def default_value(self) -> list[Substitution] | None:
        """The default, as substitutions, or None when required."""
        return self.__default_value

    @property
    def description(self) -> str:
        """The description shown by --show-args."""
        return self.__description

    @property
    def choices(self) -> list[str] | None:
        """The allowed values, or None."""
        return self.__choices

    def describe(self) -> str:
        """Return a description."""
        return f'DeclareLaunchArgument({self.__name!r})'

    def execute(self, context: LaunchContext) -> None:
        """Apply the default if unset; check required-ness and choices."""
        if self.__name not in context.launch_configurations:
            if self.__default_value is None:
                raise RuntimeError(f'Required launch argument "{self.__name}" '
                                   f'(description: "{self.__description}") was not provided')
            context.launch_configurations[self.__name] = \
                perform_substitutions(context, self.__default_value)
        value = context.launch_configurations[self.__name]
        if self.__choices is not None and value not in self.__choices:
            message = (f'Argument "{self.__name}" provided value "{value}" is not valid. '
                       f'Valid options are: {self.__choices}')
            # Jazzy logs the refusal under this action's logger before raising (errors/ 26).
            get_logger('launch.actions.declare_launch_argument').error(message)
            raise RuntimeError(message)
