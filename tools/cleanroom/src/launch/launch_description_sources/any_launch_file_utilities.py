"""Load a launch file of any supported format: Python, or a front end (XML, YAML)."""
from __future__ import annotations

import os
from collections.abc import Callable

from ..frontend.parser import InvalidFrontendLaunchFileError, Parser
from ..invalid_launch_file_error import InvalidLaunchFileError
from ..launch_description import LaunchDescription
from .frontend_launch_file_utilities import get_launch_description_from_frontend_launch_file
from .python_launch_file_utilities import get_launch_description_from_python_launch_file

__all__ = ['InvalidFrontendLaunchFileError', 'get_launch_description_from_any_launch_file']


def get_launch_description_from_any_launch_file(
        launch_file_path: str, *, parser: type[Parser] = Parser) -> LaunchDescription:
    """Try the loader the extension suggests first, then the other; report every failure.

    `.py` files are tried as Python, then as a front end; anything else the
    other way round.  When both fail, a file of a known format gets one
    ' - Type: message' line per loader (Jazzy's "Caught multiple exceptions
    ..." text); any other file (also '.xml', whose name has no extension)
    'the format is unknown', the failures kept on the error all the same.
    """
    def frontend(path: str) -> LaunchDescription:
        return get_launch_description_from_frontend_launch_file(path, parser=parser)

    extension = os.path.splitext(launch_file_path)[1].lstrip('.')
    loaders: list[Callable[[str], LaunchDescription]] = [
        get_launch_description_from_python_launch_file, frontend]
    if extension != 'py':
        loaders.reverse()
    errors: list[BaseException] = []
    for loader in loaders:
        try:
            return loader(launch_file_path)
        except Exception as error:  # noqa: BLE001 - every failure is reported below
            errors.append(error)
    if extension != 'py' and not parser.is_filename_valid(launch_file_path):
        extension = ''
    if not extension:
        raise InvalidLaunchFileError('', likely_errors=errors)
    raise InvalidLaunchFileError(extension, likely_errors=errors) from errors[0]
