"""The YAML front end: `.launch.yaml` files."""
from __future__ import annotations

import os
from typing import TextIO

import yaml
from launch import frontend
from launch.utilities.typing_file_path import FilePath

from .entity import Entity


class Parser(frontend.Parser):
    """Reads YAML with PyYAML; the file holds one key, `launch`, with a list of entities."""

    @classmethod
    def load(cls, file: FilePath | TextIO) -> tuple[Entity, Parser]:
        """Return the root entity of the YAML file and a parser for it.

        The root is checked only for its length, as on Jazzy: an empty file is
        a TypeError ("object of type 'NoneType' has no len()"), a one-item list
        an AttributeError (no `keys`).
        """
        if isinstance(file, (str, bytes, os.PathLike)):
            with open(file) as stream:
                tree = yaml.safe_load(stream)
        else:
            tree = yaml.safe_load(file)
        if len(tree) != 1:
            raise RuntimeError('Expected only one root')
        type_name = list(tree.keys())[0]
        return Entity({'children': tree[type_name] or []}, type_name), cls()

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        """yaml, yml, their launch.* forms, and launch (tried as XML and as YAML)."""
        return {'yaml', 'yml', 'launch.yaml', 'launch.yml', 'launch'}
