"""Finishing touches on the HTML of an executed lesson page.

- snippet includes get mkdocs-material's code-block title bar: the title
  line that includes.render() writes is moved into the code block;
- cells tagged ``solution`` (or ``hint``) are folded into a collapsed
  ``<details>`` block, so readers try first and look second;
- the lesson's header box goes under its title, its final Key points
  section becomes a box, and the first prose use of each glossary term
  links to the glossary (:class:`LessonPage` says what to add);
- files marked as a tab group become tabs (tabs.py).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from bs4 import BeautifulSoup

from .glossary import Entry, link_first_uses
from .keypoints import HEADING as KEY_POINTS
from .tabs import group_tabs

_TITLE = re.compile(
    r'<div class="snippet-title">(?P<title>[^<]*)</div>\s*<div class="highlight">')

FOLDED_TAGS = {'solution': ('Solution', 'success'), 'hint': ('Hint', 'tip')}


def title_snippets(html: str) -> str:
    """``<div class=snippet-title>`` + code block -> one code block with a title bar."""
    return _TITLE.sub(lambda m: f'<div class="highlight snippet"><span class="filename">'
                                f'{m.group("title")}</span>', html)


def _fold_tag(cell, tags=FOLDED_TAGS) -> str | None:
    """The folding tag of a rendered cell: nbconvert puts ``celltag_<tag>`` on the
    cell's div (code cells) or on the rendered markdown inside it."""
    for tag in tags:
        marker = f'celltag_{tag}'
        if marker in (cell.get('class') or []) or cell.select_one(f'.{marker}') is not None:
            return tag
    return None


def fold_tagged_cells(html: str) -> str:
    """Wrap each run of consecutive cells tagged solution/hint in a closed <details>."""
    if 'celltag_' not in html:
        return html
    soup = BeautifulSoup(html, 'html.parser')
    cells = [cell for cell in soup.select('div.jp-Cell')
             if cell.find_parent('div', class_='jp-Cell') is None]
    folded: set[int] = set()
    for cell in cells:
        tag = _fold_tag(cell)
        if tag is None or id(cell) in folded:
            continue
        label, kind = FOLDED_TAGS[tag]
        details = soup.new_tag('details', attrs={'class': f'{kind} textbook-{tag}'})
        summary = soup.new_tag('summary')
        summary.string = label
        details.append(summary)
        cell.insert_before(details)
        run, sibling = [cell], cell.find_next_sibling()
        while sibling is not None and 'jp-Cell' in (sibling.get('class') or []) \
                and _fold_tag(sibling) == tag:
            run.append(sibling)
            sibling = sibling.find_next_sibling()
        for member in run:
            folded.add(id(member))
            details.append(member.extract())
    return str(soup)


@dataclass
class LessonPage:
    """What the build adds to one lesson page."""

    header: str = ''
    glossary: list[Entry] = field(default_factory=list)
    glossary_url: str = ''


def _top_cell(element):
    """The notebook cell (outermost ``div.jp-Cell``) holding ``element``."""
    cells = [parent for parent in element.parents
             if parent.name == 'div' and 'jp-Cell' in (parent.get('class') or [])]
    return cells[-1] if cells else None


def add_header(soup: BeautifulSoup, header: str) -> None:
    """Put the header box right under the page title (the first h1)."""
    title = soup.find('h1')
    if title is not None and header:
        title.insert_after(BeautifulSoup(header, 'html.parser'))


def _heading_text(heading) -> str:
    return heading.get_text().replace('\u00b6', '').strip()


def box_key_points(soup: BeautifulSoup) -> bool:
    """Wrap the last Key points section (its cell and every cell after it) in a box."""
    headings = [h for h in soup.find_all('h2') if _heading_text(h) == KEY_POINTS]
    if not headings:
        return False
    first = _top_cell(headings[-1])
    if first is None:
        return False
    box = soup.new_tag('div', attrs={'class': 'admonition abstract textbook-key-points'})
    first.insert_before(box)
    cell = first
    while cell is not None:
        following = cell.find_next_sibling()
        box.append(cell.extract())
        cell = following
    return True


def finish_lesson_html(html: str, page: LessonPage | None = None) -> str:
    """The lesson HTML with title bars, folds and tabs and, given ``page``,
    header, Key points box and glossary links.  Raises TabsError for a
    malformed tab group."""
    soup = BeautifulSoup(fold_tagged_cells(title_snippets(html)), 'html.parser')
    group_tabs(soup)
    if page is not None:
        link_first_uses(soup, page.glossary, page.glossary_url)  # prose only, not the header
        add_header(soup, page.header)
        box_key_points(soup)
    return str(soup)


#: What nbconvert writes when an image output has no ``alt`` metadata.
NO_DESCRIPTION = 'No description has been provided for this image'


def images_without_description(soup: BeautifulSoup) -> list:
    """Images a screen reader could say nothing about."""
    return [image for image in soup.find_all('img')
            if not (image.get('alt') or '').strip() or image.get('alt') == NO_DESCRIPTION]
