"""Content hashes change with sources, never with tools' caches beside them
(a lint-imports run without --no-cache wrote .grimp_cache into the clean
room's sources and so re-executed every lesson)."""
from __future__ import annotations

from textbook.fingerprint import hash_paths


def test_caches_do_not_count_but_sources_do(tmp_path):
    source = tmp_path / 'pkg' / 'module.py'
    source.parent.mkdir()
    source.write_text('x = 1\n')
    before = hash_paths([tmp_path / 'pkg'], base=tmp_path)
    for cache in ('__pycache__', '.ruff_cache', '.pytest_cache', '.grimp_cache',
                  '.import_linter_cache'):
        (tmp_path / 'pkg' / cache).mkdir()
        (tmp_path / 'pkg' / cache / 'data.json').write_text('{}')
    assert hash_paths([tmp_path / 'pkg'], base=tmp_path) == before
    source.write_text('x = 2\n')
    assert hash_paths([tmp_path / 'pkg'], base=tmp_path) != before
