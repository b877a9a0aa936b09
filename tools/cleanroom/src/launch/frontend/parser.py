"""Parser: load a front-end launch file and turn its entities into actions.

Format packages register a subclass (entry point group `launch.frontend.parser`)
that implements `load()` and `get_file_extensions()`; packages adding tags
(launch_ros) register a module in `launch.frontend.launch_extension` that is
imported before the first parse.  The tags of `launch` itself are in
`launch_actions` / `launch_substitutions`.
"""
from __future__ import annotations

import os
import warnings
from importlib.metadata import entry_points
from typing import Any, TextIO

from ..action import Action
from ..invalid_launch_file_error import InvalidLaunchFileError
from ..launch_description import LaunchDescription
from ..substitution import Substitution
from ..utilities.typing_file_path import FilePath
from . import launch_actions, launch_substitutions  # noqa: F401 - register launch's own tags
from .entity import Entity
from .expose import action_parse_methods, instantiate_action
from .parse_substitution import parse_if_substitutions, parse_substitution

PARSER_GROUP = 'launch.frontend.parser'
EXTENSION_GROUP = 'launch.frontend.launch_extension'


def _file_name(file: FilePath | TextIO) -> str:
    """The name a front end is chosen by: a path's text, a file object's `name` ('' without)."""
    if isinstance(file, (str, bytes, os.PathLike)):
        return os.fsdecode(file)
    return getattr(file, 'name', '')


def file_extension(file: FilePath | TextIO) -> str:
    """'xml' for 'a.launch.xml'; '' for '.xml' or a file object without a name."""
    return os.path.splitext(_file_name(file))[1].lstrip('.')


def _implementations() -> dict[str, type[Parser]]:
    """The registered format parsers by name, found on first use."""
    Parser.load_parser_implementations()
    return Parser.frontend_parsers or {}


class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """No front end (XML, YAML) could read the launch file."""


class Parser:
    """Parse entities into actions and text into substitutions (format independent)."""

    frontend_parsers: dict[str, type[Parser]] | None = None
    extensions_loaded = False

    @classmethod
    def load_launch_extensions(cls) -> None:
        """Import every registered launch extension (e.g. launch_ros' tags) once.

        Jazzy does this on the first `parse_action`, not when a parser is made,
        and keeps the flag on the class it was asked through (launch_xml's Parser
        after a parse): `Parser.extensions_loaded` may stay False.
        """
        if cls.extensions_loaded:
            return
        for entry_point in entry_points(group=EXTENSION_GROUP):
            entry_point.load()
        cls.extensions_loaded = True

    @classmethod
    def load_parser_implementations(cls) -> None:
        """Find the format parsers (launch_xml, launch_yaml) once."""
        if Parser.frontend_parsers is None:
            Parser.frontend_parsers = {
                entry_point.name: entry_point.load()
                for entry_point in entry_points(group=PARSER_GROUP)}

    def parse_action(self, entity: Entity) -> Action:
        """Build the action of `entity`; RuntimeError for a tag nobody registered."""
        self.load_launch_extensions()
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
        """The file name endings this parser reads (none for the base class)."""
        return set()

    @classmethod
    def get_file_extensions_from_parsers(cls) -> set[str]:
        """Every file name ending some format parser reads."""
        return set().union(*(p.get_file_extensions() for p in _implementations().values()))

    @classmethod
    def get_available_extensions(cls) -> list[str]:
        """The format parsers' registered names (Jazzy returns the dict's keys view)."""
        return _implementations().keys()  # type: ignore[return-value]

    @classmethod
    def is_extension_valid(cls, extension: str) -> bool:
        """Deprecated: whether a format parser is registered under `extension`."""
        warnings.warn(  # stacklevel 1: Jazzy's warning names this line, not the caller
            'Parser.is_extension_valid is deprecated, use Parser.is_filename_valid instead',
            stacklevel=1)
        return extension in _implementations()

    @classmethod
    def get_parser_from_extension(cls, extension: str) -> type[Parser] | None:
        """Deprecated: the format parser registered under `extension`."""
        warnings.warn('Parser.get_parser_from_extension is deprecated, '
                      'use Parser.get_parsers_from_filename instead', stacklevel=1)
        try:
            return _implementations()[extension]
        except KeyError:
            raise RuntimeError('Not recognized frontend implementation')  # noqa: B904 - as Jazzy

    @classmethod
    def may_parse(cls, filename: str) -> bool:
        """True when `filename` ends in '.' and one of this parser's extensions.

        Only text has an ending: a file object or path fails (AttributeError)
        as on Jazzy, unless the parser has no extensions to compare.
        """
        return any(filename.endswith(f'.{extension}') for extension in cls.get_file_extensions())

    @classmethod
    def get_parsers_from_filename(cls, filename: str) -> list[type[Parser]]:
        """The format parsers whose extension fits the file name."""
        return [p for p in _implementations().values() if p.may_parse(filename)]

    @classmethod
    def is_filename_valid(cls, filename: str) -> bool:
        """True when some format parser reads files named like this."""
        return bool(cls.get_parsers_from_filename(filename))

    @classmethod
    def load(cls, file: FilePath | TextIO) -> tuple[Entity, Parser]:
        """Read the file with the parsers its name fits first, then with every other.

        A path is opened first (a missing file is a FileNotFoundError); a file
        object is used as given and, as on Jazzy, rewound to its very start
        after each failed parser (a stream that cannot seek fails there).  A
        file object without a name fits no parser: all are tried.  When all
        fail, the error lists every parser's failure for a name with a known
        extension, and otherwise says the format is unknown (the failures are
        still kept on it).
        """
        name = _file_name(file)
        implementations = list(_implementations().values())
        matching = cls.get_parsers_from_filename(name)
        errors: list[BaseException] = []
        opened = isinstance(file, (str, bytes, os.PathLike))
        stream = open(file) if opened else file  # noqa: SIM115 - closed below
        try:
            for implementation in matching + [p for p in implementations if p not in matching]:
                try:
                    return implementation.load(stream)
                except Exception as error:  # noqa: BLE001 - every failure is reported below
                    errors.append(error)
                    stream.seek(0)
        finally:
            if opened:
                stream.close()
        extension = file_extension(name)
        if not matching or not extension:
            raise InvalidFrontendLaunchFileError('', likely_errors=errors)
        raise InvalidFrontendLaunchFileError(extension, likely_errors=errors) from errors[0]
