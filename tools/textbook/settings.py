"""Execution settings of the book's build, from ``[tool.textbook]`` in pyproject.toml.

An environment variable of the same name in capitals with a ``TEXTBOOK_``
prefix overrides a value for one run (``TEXTBOOK_JOBS=1 make site``).
"""
from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass, fields

from . import paths


@dataclass(frozen=True)
class Settings:
    cell_timeout: int = 300  # seconds; a cell that runs longer is reported as hung
    jobs: int = 2            # lessons executed at the same time by the site build
    fresh: bool = False      # tests execute every lesson even when its result is cached
    test_workers: int = 2    # pytest-xdist workers of `python -m textbook test`


def _value(name: str, raw: object, default: object) -> object:
    if isinstance(default, bool):
        text = str(raw).strip().lower()
        if text not in ('1', '0', 'true', 'false'):
            raise ValueError(f'{name}: expected true or false, got {raw!r}')
        return text in ('1', 'true')
    try:
        value = int(raw)
    except (TypeError, ValueError):
        raise ValueError(f'{name}: expected a whole number, got {raw!r}') from None
    if value < 1:
        raise ValueError(f'{name}: expected at least 1, got {value}')
    return value


def load(pyproject: os.PathLike | None = None, environ: dict[str, str] | None = None) -> Settings:
    """The settings: defaults, then pyproject.toml, then TEXTBOOK_* variables."""
    path = paths.ROOT / 'pyproject.toml' if pyproject is None else pyproject
    with open(path, 'rb') as handle:
        table = tomllib.load(handle).get('tool', {}).get('textbook', {})
    environ = os.environ if environ is None else environ
    known = {field.name: field.default for field in fields(Settings)}
    unknown = set(table) - set(known)
    if unknown:
        raise ValueError(f"{path}: [tool.textbook] has unknown setting(s) "
                         f"{', '.join(sorted(unknown))}; known: {', '.join(known)}")
    values = {}
    for name, default in known.items():
        raw = environ.get(f'TEXTBOOK_{name.upper()}', table.get(name, default))
        values[name] = _value(f'TEXTBOOK_{name.upper()}' if f'TEXTBOOK_{name.upper()}' in environ
                              else f'{path} [tool.textbook] {name}', raw, default)
    return Settings(**values)
