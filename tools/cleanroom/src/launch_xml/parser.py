"""The XML front end: `.launch.xml` files."""
from __future__ import annotations

import io
import os
import xml.etree.ElementTree as ET
from typing import TextIO

from launch import frontend

from .entity import Entity


class Parser(frontend.Parser):
    """Reads XML with xml.etree; its errors (ParseError) reach the user unchanged."""

    @classmethod
    def load(cls, file: str | os.PathLike | TextIO) -> tuple[Entity, Parser]:
        """Return the root entity of the XML file and a parser for it."""
        source = file if isinstance(file, (str, os.PathLike)) else io.StringIO(file.read())
        return Entity(ET.parse(source).getroot()), cls()

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        """xml, launch.xml and launch (a `.launch` file is tried as XML and as YAML)."""
        return {'xml', 'launch.xml', 'launch'}
