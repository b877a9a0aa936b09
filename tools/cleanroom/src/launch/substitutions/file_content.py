"""The content of a file."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class FileContent(Substitution):
    """The text of the file at `path`; fails naming the path if it cannot be read."""

    def __init__(self, path: SomeSubstitutionsType) -> None:
        super().__init__()
        self.__path = normalize_to_list_of_substitutions(path)

    @property
    def path(self) -> list[Substitution]:
        """The path, as substitutions."""
        return self.__path

    def describe(self) -> str:
        """Return e.g. FileContent('/etc/hostname')."""
        return f"FileContent({' + '.join(s.describe() for s in self.__path)})"

    def perform(self, context: LaunchContext) -> str:
        """Return the file's text."""
        path = perform_substitutions(context, self.__path)
        try:
            with open(path) as f:
                return f.read()
        except OSError as exc:
            raise SubstitutionFailure(f"Failed to read file '{path}': {exc.strerror}") from exc
