"""Where a LaunchDescription comes from: given directly, or loaded from a location."""
from __future__ import annotations

from typing import TYPE_CHECKING

from .launch_context import LaunchContext
from .launch_description import LaunchDescription
from .utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from .some_substitutions_type import SomeSubstitutionsType


class LaunchDescriptionSource:
    """Gives a LaunchDescription, loading it from `location` the first time if needed.

    The location may contain substitutions; it is expanded in the context of
    the including action, so a path can depend on launch configurations.
    """

    def __init__(self, launch_description: LaunchDescription | None = None,
                 location: SomeSubstitutionsType = '<string>',
                 method: str = 'interpreted launch file') -> None:
        self.__launch_description = launch_description
        self.__location = normalize_to_list_of_substitutions(location)
        self.__expanded_location: str | None = None
        self.__method = method

    @property
    def location(self) -> str:
        """The expanded location, or its description before it was expanded."""
        if self.__expanded_location is not None:
            return self.__expanded_location
        return ' + '.join(s.describe() for s in self.__location)

    @property
    def method(self) -> str:
        """How the description is obtained."""
        return self.__method

    def try_get_launch_description_without_context(self) -> LaunchDescription | None:
        """Best-effort load for introspection (--show-args); None when not possible."""
        if self.__launch_description is not None:
            return self.__launch_description

        try:
            location = perform_substitutions(LaunchContext(), self.__location)
            return self._get_launch_description(location)
        except Exception:  # noqa: BLE001 - introspection must not fail the launch
            return None

    def get_launch_description(self, context: LaunchContext) -> LaunchDescription:
        """Expand the location in `context` and return the (loaded) description."""
        if self.__expanded_location is None:
            self.__expanded_location = perform_substitutions(context, self.__location)
        if self.__launch_description is None:
            self.__launch_description = self._get_launch_description(self.__expanded_location)
        return self.__launch_description

    def _get_launch_description(self, location: str) -> LaunchDescription:
        raise RuntimeError(f"LaunchDescriptionSource has no launch description for '{location}'")
