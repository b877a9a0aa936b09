"""The glossary (docs/glossary.md) and its links from lesson prose.

Each entry of the glossary is a heading ``## Title {#anchor data-terms="a|b"}``
followed by its definition; ``data-terms`` lists the words that link to it
(default: the title in lower case).  On a lesson page the first use of each
term in prose becomes a link to its entry, so lessons never link by hand.
Code, headings, links and figure captions are never touched.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from html import unescape
from pathlib import Path

from bs4 import BeautifulSoup, NavigableString

from . import paths

GLOSSARY = paths.DOCS / 'glossary.md'
_ENTRY = re.compile(r'^## (?P<title>.+?) \{#(?P<anchor>[a-z0-9-]+)'
                    r'(?: data-terms="(?P<terms>[^"]*)")?\}\s*$')
#: Text inside these elements is never linked.
_NOT_PROSE = {'code', 'pre', 'a', 'h1', 'h2', 'h3', 'h4', 'h5', 'h6', 'summary',
              'figcaption', 'script', 'style', 'kbd'}


class GlossaryError(ValueError):
    """docs/glossary.md has a malformed entry."""


@dataclass(frozen=True)
class Entry:
    title: str
    anchor: str
    terms: tuple[str, ...]
    definition: str


def load(path: Path = GLOSSARY) -> list[Entry]:
    """The entries of the glossary, in file order; a bad entry names its line."""
    entries: list[Entry] = []
    lines = path.read_text().splitlines()
    for number, line in enumerate(lines, start=1):
        if not line.startswith('## '):
            continue
        match = _ENTRY.match(line)
        if match is None:
            raise GlossaryError(f'{paths.rel(path)}:{number}: a glossary entry is '
                                f'"## Title {{#anchor}}" or "## Title {{#anchor '
                                f'data-terms="term|term"}}", got: {line}')
        terms = match['terms'] or match['title'].lower()
        entries.append(Entry(match['title'], match['anchor'],
                             tuple(t.strip() for t in terms.split('|') if t.strip()),
                             _definition(lines[number:])))
    return entries


def _definition(following: list[str]) -> str:
    """The first paragraph after a heading, as plain text (a link's tooltip)."""
    paragraph: list[str] = []
    for line in following:
        if line.startswith('#') or (not line.strip() and paragraph):
            break
        if line.strip():
            paragraph.append(line.strip())
    text = re.sub(r'\[([^\]]*)\]\([^)]*\)', r'\1', ' '.join(paragraph))
    return unescape(text.replace('`', '').replace('**', '').replace('*', ''))


def _pattern(entries: list[Entry]) -> re.Pattern[str]:
    """All terms, longest first, so 'launch argument' wins over 'argument'."""
    terms = sorted({t for e in entries for t in e.terms}, key=len, reverse=True)
    alternatives = '|'.join(re.escape(t) for t in terms)
    return re.compile(rf'(?<![\w/.-])({alternatives})(?![\w-]|\.\w)', re.IGNORECASE)


def _is_prose(node: NavigableString) -> bool:
    return not any(parent.name in _NOT_PROSE for parent in node.parents)


def link_first_uses(soup: BeautifulSoup, entries: list[Entry], glossary_url: str,
                    within: str = 'div.jp-MarkdownCell div.jp-RenderedMarkdown') -> list[str]:
    """Link the first prose use of every term under ``within`` (markdown cells, never
    a cell's output, which stays as printed); returns the anchors linked."""
    if not entries:
        return []
    by_term = {t.lower(): e for e in entries for t in e.terms}
    pattern = _pattern(entries)
    linked: set[str] = set()
    for container in soup.select(within):
        for node in list(container.find_all(string=True)):
            if isinstance(node, NavigableString) and type(node) is NavigableString \
                    and _is_prose(node):
                _link_in(soup, node, pattern, by_term, linked, glossary_url)
    return sorted(linked)


def _link_in(soup: BeautifulSoup, node: NavigableString, pattern: re.Pattern[str],
             by_term: dict[str, Entry], linked: set[str], glossary_url: str) -> None:
    """Replace ``node`` by text and links for terms not linked yet."""
    text, pieces, start = str(node), [], 0
    for match in pattern.finditer(text):
        entry = by_term[match.group(1).lower()]
        if entry.anchor in linked:
            continue
        linked.add(entry.anchor)
        pieces.append(text[start:match.start()])
        link = soup.new_tag('a', attrs={'class': 'glossary-term',
                                        'href': f'{glossary_url}#{entry.anchor}',
                                        'title': entry.definition})
        link.string = match.group(1)
        pieces.append(link)
        start = match.end()
    if not pieces:
        return
    pieces.append(text[start:])
    for piece in pieces:
        node.insert_before(piece if not isinstance(piece, str) else NavigableString(piece))
    node.extract()
