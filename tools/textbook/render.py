"""Finishing touches on the HTML of an executed lesson page.

- snippet includes get mkdocs-material's code-block title bar: the title
  line that includes.render() writes is moved into the code block;
- cells tagged ``solution`` (or ``hint``) are folded into a collapsed
  ``<details>`` block, so readers try first and look second.
"""
from __future__ import annotations

import re

from bs4 import BeautifulSoup

_TITLE = re.compile(
    r'<div class="snippet-title">(?P<title>[^<]*)</div>\s*<div class="highlight">')

FOLDED_TAGS = {"solution": ("Solution", "success"), "hint": ("Hint", "tip")}


def title_snippets(html: str) -> str:
    """``<div class=snippet-title>`` + code block -> one code block with a title bar."""
    return _TITLE.sub(lambda m: f'<div class="highlight snippet"><span class="filename">'
                                f'{m.group("title")}</span>', html)


def _fold_tag(cell, tags=FOLDED_TAGS) -> str | None:
    """The folding tag of a rendered cell: nbconvert puts ``celltag_<tag>`` on the
    cell's div (code cells) or on the rendered markdown inside it."""
    for tag in tags:
        marker = f"celltag_{tag}"
        if marker in (cell.get("class") or []) or cell.select_one(f".{marker}") is not None:
            return tag
    return None


def fold_tagged_cells(html: str) -> str:
    """Wrap each run of consecutive cells tagged solution/hint in a closed <details>."""
    if "celltag_" not in html:
        return html
    soup = BeautifulSoup(html, "html.parser")
    cells = [cell for cell in soup.select("div.jp-Cell")
             if cell.find_parent("div", class_="jp-Cell") is None]
    folded: set[int] = set()
    for cell in cells:
        tag = _fold_tag(cell)
        if tag is None or id(cell) in folded:
            continue
        label, kind = FOLDED_TAGS[tag]
        details = soup.new_tag("details", attrs={"class": f"{kind} textbook-{tag}"})
        summary = soup.new_tag("summary")
        summary.string = label
        details.append(summary)
        cell.insert_before(details)
        run, sibling = [cell], cell.find_next_sibling()
        while sibling is not None and "jp-Cell" in (sibling.get("class") or []) \
                and _fold_tag(sibling) == tag:
            run.append(sibling)
            sibling = sibling.find_next_sibling()
        for member in run:
            folded.add(id(member))
            details.append(member.extract())
    return str(soup)


def finish_lesson_html(html: str) -> str:
    return fold_tagged_cells(title_snippets(html))
