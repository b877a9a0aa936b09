"""Parser: load a front-end launch file and turn its entities into actions.

Format packages register a subclass (entry point group `launch.frontend.parser`)
that implements `load()` and `get_file_extensions()`; packages adding tags
(launch_ros) register a module in `launch.frontend.launch_extension` that is
imported before the first parse.  The tags of `launch` itself are in
`launch_actions` / `launch_substitutions`.
"""
from __future__ import annotations

import os
from importlib.metadata import entry_points
from typing import Any, TextIO

from ..action import Action
from ..invalid_launch_file_error import InvalidLaunchFileError
from ..launch_description import LaunchDescription
from ..substitution import Substitution
from . import launch_actions, launch_substitutions  # noqa: F401 - register launch's own tags
from .entity import Entity
from .expose import action_parse_methods, instantiate_action
from .parse_substitution import parse_if_substitutions, parse_substitution

PARSER_GROUP = 'launch.frontend.parser'
EXTENSION_GROUP = 'launch.frontend.launch_extension'


def _file_name(file: str | TextIO) -> str:
    return file if isinstance(file, str) else getattr(file, 'name', '')


def file_extension(file: str | TextIO) -> str:
    """'xml' for 'a.launch.xml'."""
    return os.path.splitext(_file_name(file))[1].lstrip('.')


class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """No front end (XML, YAML) could read the launch file."""


class Parser:
    """Parse entities into actions and text into substitutions (format independent)."""

    frontend_parsers: dict[str, type[Parser]] | None = None
    extensions_loaded = False

    def __init__(self) -> None:
        self.load_launch_extensions()

    @classmethod
    def load_launch_extensions(cls) -> None:
        """Import every registered launch extension (e.g. launch_ros' tags) once."""
        if Parser.extensions_loaded:
            return
        for entry_point in entry_points(group=EXTENSION_GROUP):
            entry_point.load()
        Parser.extensions_loaded = True

    @classmethod
    def load_parser_implementations(cls) -> None:
        """Find the format parsers (launch_xml, launch_yaml) once."""
        if Parser.frontend_parsers is None:
            Parser.frontend_parsers = {
                entry_point.name: entry_point.load()
                for entry_point in entry_points(group=PARSER_GROUP)}

    def parse_action(self, entity: Entity) -> Action:
        """Build the action of `entity`; RuntimeError for a tag nobody registered."""
        if entity.type_name not in action_parse_methods:
            raise RuntimeError(f'Unrecognized entity of the type: {entity.type_name}')
        action = instantiate_action(entity, self)
        entity.assert_entity_completely_parsed()
        return action

    def parse_description(self, entity: Entity) -> LaunchDescription:
        """Build the LaunchDescription of the root `launch` entity."""
        if entity.type_name != 'launch':
            raise RuntimeError("Expected 'launch' as root tag")
        entity.get_attr('version', optional=True)
        actions = [self.parse_action(child) for child in entity.children]
        entity.assert_entity_completely_parsed()
        return LaunchDescription(actions)

    def parse_substitution(self, value: str) -> list[Substitution]:
        """Parse `$(...)` substitutions in `value`."""
        return parse_substitution(self.escape_characters(value))

    def parse_if_substitutions(self, value: Any) -> Any:
        """Parse text (and lists of text) for substitutions; other values pass through."""
        return parse_if_substitutions(value)

    def escape_characters(self, value: str) -> str:
        """Format-specific escaping; none by default."""
        return value

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        """The file extensions this parser reads (none for the base class)."""
        return set()

    @classmethod
    def get_available_extensions(cls) -> list[str]:
        """Extensions of every registered format parser."""
        cls.load_parser_implementations()
        return sorted(set().union(*(p.get_file_extensions()
                                    for p in (Parser.frontend_parsers or {}).values())))

    @classmethod
    def may_parse(cls, file: str | TextIO) -> bool:
        """True when the file's extension is one of this parser's."""
        return file_extension(file) in cls.get_file_extensions()

    @classmethod
    def get_parsers_from_filename(cls, file: str | TextIO) -> list[type[Parser]]:
        """The format parsers whose extension fits the file."""
        cls.load_parser_implementations()
        return [p for p in (Parser.frontend_parsers or {}).values() if p.may_parse(file)]

    @classmethod
    def is_filename_valid(cls, file: str | TextIO) -> bool:
        """True when some format parser reads files named like this."""
        return bool(cls.get_parsers_from_filename(file))

    @classmethod
    def load(cls, file: str | TextIO) -> tuple[Entity, Parser]:
        """Read the file (a path is opened first: a missing file is a FileNotFoundError)
        with the parsers of its extension, then with every other; a file object is
        read again from where it started for each.  When all fail: every parser's
        error for a file of a known format, else 'the format is unknown'."""
        matching = cls.get_parsers_from_filename(file)  # loads the implementations
        implementations = list((Parser.frontend_parsers or {}).values())
        errors: list[BaseException] = []
        stream = open(file) if isinstance(file, str) else file  # noqa: SIM115 - closed below
        start = stream.tell() if stream.seekable() else None
        try:
            for implementation in matching + [p for p in implementations if p not in matching]:
                if start is not None:
                    stream.seek(start)
                try:
                    return implementation.load(stream)
                except Exception as error:  # noqa: BLE001 - every failure is reported below
                    errors.append(error)
        finally:
            if stream is not file:
                stream.close()
        if not matching:
            raise InvalidFrontendLaunchFileError('')
        raise InvalidFrontendLaunchFileError(file_extension(file),
                                             likely_errors=errors) from errors[0]
