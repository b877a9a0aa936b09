"""Every lesson ends with a ``## Key points`` section: what a student keeps.

The check runs with the other lesson checks (``textbook check``), so a
lesson without it fails before anything executes; on the page the section
becomes a box (:func:`textbook.render.finish_lesson_html`).
"""
from __future__ import annotations

from markdown_it import MarkdownIt
from mdit_py_plugins.front_matter import front_matter_plugin

HEADING = 'Key points'
_PARSER = MarkdownIt('commonmark').use(front_matter_plugin)


class KeyPointsError(ValueError):
    """A lesson does not end with its Key points section."""


def sections(text: str) -> list[tuple[int, str]]:
    """(1-based line, title) of every ``##`` heading outside code, in order."""
    tokens = _PARSER.parse(text)
    return [(token.map[0] + 1, tokens[index + 1].content.strip())
            for index, token in enumerate(tokens)
            if token.type == 'heading_open' and token.tag == 'h2' and token.map]


def check(text: str, source: str) -> None:
    """Raise naming file and line unless the last ``##`` section is Key points."""
    found = sections(text)
    if not found:
        line = text.count('\n') + 1
        raise KeyPointsError(f"{source}:{line}: the lesson has no '## {HEADING}' section; "
                             f"end it with one listing what the student should keep")
    line, title = found[-1]
    if title != HEADING:
        raise KeyPointsError(f"{source}:{line}: the last section is '## {title}'; a lesson "
                             f"ends with a '## {HEADING}' section")
