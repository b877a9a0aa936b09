"""The table of contents of a lesson page, read from its rendered headings.

mkdocs-jupyter builds the TOC from the notebook's markdown with inline code
stripped ("Start it with" for "Start it with `ros2 launch`") and anchors
that no longer match the headings; reading the headings of the finished
HTML keeps their code and their real ids.
"""
from __future__ import annotations

from typing import Any

from bs4 import BeautifulSoup

HEADINGS = ['h1', 'h2', 'h3']


def toc_tokens(soup: BeautifulSoup) -> list[dict[str, Any]]:
    """Nested tokens (level, id, name, children) as mkdocs.structure.toc.get_toc takes."""
    roots: list[dict[str, Any]] = []
    stack: list[dict[str, Any]] = []
    for heading in soup.find_all(HEADINGS):
        if not heading.get('id'):
            continue
        title = BeautifulSoup(str(heading), 'html.parser').find(heading.name)
        for anchor in title.select('a.anchor-link, a.headerlink'):
            anchor.decompose()
        token = {'level': int(heading.name[1]), 'id': heading['id'],
                 'name': title.decode_contents().strip(), 'children': []}
        while stack and stack[-1]['level'] >= token['level']:
            stack.pop()
        (stack[-1]['children'] if stack else roots).append(token)
        stack.append(token)
    return roots
