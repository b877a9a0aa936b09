"""Error raised when a launch file cannot be loaded."""
from __future__ import annotations

from collections.abc import Sequence

_UNKNOWN_FORMAT = 'The launch file may have a syntax error, or its format is unknown'


class InvalidLaunchFileError(Exception):
    """A launch file could not be loaded with any of the tried loaders.

    ``extension`` is the format the file was taken for ('' when its name says
    none) and ``likely_errors`` what each loader raised: Jazzy's message lists
    them (' - Type: message' each) for a known format, and otherwise says the
    format is unknown.
    """

    def __init__(self, extension: str = '', *,
                 likely_errors: Sequence[BaseException] | None = None) -> None:
        self._extension = extension
        self._likely_errors = likely_errors
        if extension == '' or not likely_errors:
            self._error_message = _UNKNOWN_FORMAT
        else:
            caught = ('Caught exception' if len(likely_errors) == 1
                      else 'Caught multiple exceptions')
            self._error_message = (
                f'{caught} when trying to load file of format [{extension}]:'
                + ''.join(f'\n - {type(error).__name__}: {error}' for error in likely_errors))

    def __str__(self) -> str:
        return self._error_message
