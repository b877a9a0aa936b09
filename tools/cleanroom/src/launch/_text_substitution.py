"""Plain text as a substitution.

Below `launch.utilities` on purpose: `normalize_to_list_of_substitutions`
turns text into TextSubstitution, and every substitution uses that helper.
The public home stays `launch.substitutions.text_substitution`.
"""

from .substitution import Substitution


class TextSubstitution(Substitution):
    """Substitution that is a fixed text."""

    def __init__(self, *, text: str) -> None:
        super().__init__()
        if not isinstance(text, str):
            raise TypeError(f"TextSubstitution expected Text object got '{type(text)}' instead.")
        self.__text = text

    @property
    def text(self) -> str:
        """The text."""
        return self.__text

    def describe(self) -> str:
        """Return the text quoted, as `ros2 launch --show-args` prints defaults."""
        return f"'{self.__text}'"

    def perform(self, context: object) -> str:
        """Return the text."""
        return self.__text


# Shown in reprs and error messages as Jazzy names it.
TextSubstitution.__module__ = 'launch.substitutions.text_substitution'
