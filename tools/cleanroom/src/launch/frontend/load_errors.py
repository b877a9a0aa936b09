"""The text Jazzy gives when every loader of a launch file failed."""
from __future__ import annotations

from collections.abc import Sequence

from ..invalid_launch_file_error import InvalidLaunchFileError

UNKNOWN_FORMAT = 'The launch file may have a syntax error, or its format is unknown'


def describe_load_errors(extension: str, errors: Sequence[BaseException]) -> str:
    """One exception: 'Caught exception ...'; several: one ' - Type: message' line each."""
    if len(errors) == 1:
        return (f'Caught exception when trying to load file of format [{extension}]: '
                f'{errors[0]}')
    lines = [f'Caught multiple exceptions when trying to load file of format [{extension}]:']
    lines += [f' - {type(error).__name__}: {error}' for error in errors]
    return '\n'.join(lines)


class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """No front end (XML, YAML) could read the launch file."""
