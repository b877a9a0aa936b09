"""The built site, shared by the site tests: one strict build per session.

``TEXTBOOK_SITE_DIR=<folder>`` tests a site already built there instead
(for iterating on the tests; CI always builds).
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from textbook import paths


@pytest.fixture(scope='session')
def site(tmp_path_factory):
    if os.environ.get('TEXTBOOK_SITE_DIR'):
        return Path(os.environ['TEXTBOOK_SITE_DIR'])
    site_dir = tmp_path_factory.mktemp('site')
    result = subprocess.run(
        [sys.executable, '-m', 'mkdocs', 'build', '--strict', '-f', str(paths.MKDOCS_YML),
         '-d', str(site_dir)],
        cwd=paths.ROOT, env=dict(os.environ, NO_MKDOCS_2_WARNING='1'),
        capture_output=True, text=True, timeout=1800)
    assert result.returncode == 0, result.stdout + result.stderr
    assert 'WARNING' not in result.stderr, result.stderr
    return site_dir
