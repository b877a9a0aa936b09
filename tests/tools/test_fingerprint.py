"""Content hashes change with sources, never with tools' caches beside them
(a lint-imports run without --no-cache wrote .grimp_cache into the clean
room's sources and so re-executed every lesson); the tools are hashed once
per process, not once per lesson key."""
from __future__ import annotations

import pytest
from textbook import cache, paths
from textbook.fingerprint import hash_paths


def test_caches_do_not_count_but_sources_do(tmp_path):
    source = tmp_path / 'pkg' / 'module.py'
    source.parent.mkdir()
    source.write_text('x = 1\n')
    before = hash_paths([tmp_path / 'pkg'], base=tmp_path)
    for tool_cache in ('__pycache__', '.ruff_cache', '.pytest_cache', '.grimp_cache',
                       '.import_linter_cache'):
        (tmp_path / 'pkg' / tool_cache).mkdir()
        (tmp_path / 'pkg' / tool_cache / 'data.json').write_text('{}')
    assert hash_paths([tmp_path / 'pkg'], base=tmp_path) == before
    source.write_text('x = 2\n')
    assert hash_paths([tmp_path / 'pkg'], base=tmp_path) != before


@pytest.fixture
def tools_tree(tmp_path, monkeypatch):
    """A small tools/ tree in place of the real one; the process-wide hash starts fresh."""
    for relative in ('tools/labkit/graph.py', 'tools/cleanroom/src/launch/action.py',
                     'requirements/lock.txt'):
        (tmp_path / relative).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / relative).write_text(f'# {relative}\n')
    monkeypatch.setattr(paths, 'ROOT', tmp_path)
    monkeypatch.setattr(paths, 'TOOLS', tmp_path / 'tools')
    monkeypatch.setattr(cache, '_EXECUTION_MODULES', [])
    cache.tools_sources_hash.cache_clear()
    yield tmp_path
    cache.tools_sources_hash.cache_clear()  # the next user hashes the real tree


def test_tools_are_read_once_per_process(tools_tree, monkeypatch):
    reads = []
    real_hash_paths = cache.hash_paths
    monkeypatch.setattr(cache, 'hash_paths',
                        lambda *args, **kwargs: reads.append(1) or real_hash_paths(*args, **kwargs))
    first = cache.tools_fingerprint()
    assert [cache.tools_fingerprint() for _ in range(3)] == [first] * 3
    assert len(reads) == 1


def test_an_edited_tool_counts_once_the_hash_is_cleared(tools_tree, monkeypatch):
    before = cache.tools_fingerprint()
    (tools_tree / 'tools' / 'labkit' / 'graph.py').write_text('# changed\n')
    assert cache.tools_fingerprint() == before  # read once: the edit is not seen yet
    cache.tools_sources_hash.cache_clear()
    assert cache.tools_fingerprint() != before
    monkeypatch.setattr(cache, '__version__', '99.0')  # the cheap parts stay live
    assert cache.tools_fingerprint() != before
