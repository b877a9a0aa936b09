"""Plain text as a substitution."""

from ..substitution import Substitution


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
