"""The YAML front end: `.launch.yaml` files."""
from __future__ import annotations

from typing import TextIO

import yaml
from launch import frontend

from .entity import Entity


class Parser(frontend.Parser):
    """Reads YAML with PyYAML; the file holds one key, `launch`, with a list of entities."""

    @classmethod
    def load(cls, file: str | TextIO) -> tuple[Entity, Parser]:
        """Return the root entity of the YAML file and a parser for it."""
        if isinstance(file, str):
            with open(file) as stream:
                tree = yaml.safe_load(stream)
        else:
            tree = yaml.safe_load(file)
        if tree is None or len(tree) != 1:
            raise RuntimeError('Expected only one root')
        if not isinstance(tree, dict):
            raise RuntimeError('Expected a mapping as root')
        (type_name, body), = tree.items()
        return Entity({'children': body or []}, type_name), cls()

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        """yaml and yml."""
        return {'yaml', 'yml'}
