"""Load a front-end (XML, YAML) launch file into a LaunchDescription."""
from __future__ import annotations

from ..frontend.parser import InvalidFrontendLaunchFileError, Parser
from ..launch_description import LaunchDescription

__all__ = ['InvalidFrontendLaunchFileError', 'get_launch_description_from_frontend_launch_file']


def get_launch_description_from_frontend_launch_file(
        frontend_launch_file_path: str, *, parser: type[Parser] = Parser) -> LaunchDescription:
    """Read the file with `parser` (by default: the format of its extension) and parse it."""
    root_entity, parser_instance = parser.load(frontend_launch_file_path)
    return parser_instance.parse_description(root_entity)
