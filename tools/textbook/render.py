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


def fold_tagged_cells(html: str) -> str:
    """Wrap each run of consecutive cells tagged solution/hint in a closed <details>."""
    if not any(f"celltag_{tag}" in html for tag in FOLDED_TAGS):
        return html
    soup = BeautifulSoup(html, "html.parser")
    for tag, (label, kind) in FOLDED_TAGS.items():
        for cell in soup.select(f"div.celltag_{tag}"):
            if cell.parent is not None and cell.parent.name == "details":
                continue  # already folded with the cell before it
            details = soup.new_tag("details", attrs={"class": f"{kind} textbook-{tag}"})
            summary = soup.new_tag("summary")
            summary.string = label
            details.append(summary)
            cell.insert_before(details)
            run = [cell]
            sibling = cell.find_next_sibling()
            while sibling is not None and f"celltag_{tag}" in (sibling.get("class") or []):
                run.append(sibling)
                sibling = sibling.find_next_sibling()
            for member in run:
                details.append(member.extract())
    return str(soup)


def finish_lesson_html(html: str) -> str:
    return fold_tagged_cells(title_snippets(html))
