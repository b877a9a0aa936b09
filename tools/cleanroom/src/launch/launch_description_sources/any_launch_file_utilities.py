"""Load a launch file of any supported format (here: Python)."""
from __future__ import annotations

import os

from ..invalid_launch_file_error import InvalidLaunchFileError
from ..launch_description import LaunchDescription
from .python_launch_file_utilities import get_launch_description_from_python_launch_file

FRONTEND_FAILURE = 'The launch file may have a syntax error, or its format is unknown'


class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """No XML/YAML frontend could parse the file."""


def get_launch_description_from_any_launch_file(launch_file_path: str) -> LaunchDescription:
    """Try the loaders that fit the extension; report every failure if all fail.

    The clean room has no XML/YAML frontend, so after Python the frontend
    attempt always fails, as Jazzy's does for a file it cannot parse.
    """
    extension = os.path.splitext(launch_file_path)[1].lstrip('.')
    errors = []
    if extension == 'py':
        try:
            return get_launch_description_from_python_launch_file(launch_file_path)
        except Exception as exc:  # noqa: BLE001 - reported below with the others
            errors.append(exc)
    errors.append(InvalidFrontendLaunchFileError(FRONTEND_FAILURE))
    if len(errors) == 1:
        raise InvalidLaunchFileError(
            f'Caught exception when trying to load file of format [{extension}]: '
            f'{FRONTEND_FAILURE}')
    lines = [f'Caught multiple exceptions when trying to load file of format [{extension}]:']
    lines += [f' - {type(exc).__name__}: {exc}' for exc in errors]
    raise InvalidLaunchFileError('\n'.join(lines)) from errors[0]
