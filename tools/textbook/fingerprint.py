"""Content hashes: the keys that decide when something must be redone."""
from __future__ import annotations

import hashlib
from collections.abc import Iterable
from pathlib import Path

#: Caches that tools write beside sources; their content is not the sources'.
_SKIP_PARTS = {'__pycache__', '.pytest_cache', '.ruff_cache', '.grimp_cache',
               '.import_linter_cache'}
_SKIP_SUFFIXES = ('.pyc', '.pyo')


def tree_files(root: Path) -> list[Path]:
    """Every regular file under ``root`` that matters for content, in a stable order."""
    if root.is_file():
        return [root]
    if not root.is_dir():
        return []
    return sorted(
        p for p in root.rglob('*')
        if p.is_file() and not _SKIP_PARTS.intersection(p.parts)
        and not p.name.endswith(_SKIP_SUFFIXES) and '.egg-info' not in str(p)
    )


def hash_paths(paths: Iterable[Path], base: Path | None = None) -> str:
    """sha256 over the names and contents of all files under ``paths``."""
    digest = hashlib.sha256()
    for root in paths:
        for file in tree_files(Path(root)):
            name = file.relative_to(base) if base else file
            digest.update(str(name).encode() + b'\0')
            digest.update(file.read_bytes() + b'\0')
    return digest.hexdigest()


def hash_text(*parts: str) -> str:
    digest = hashlib.sha256()
    for part in parts:
        digest.update(part.encode() + b'\0')
    return digest.hexdigest()
