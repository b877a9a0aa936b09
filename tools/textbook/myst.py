"""Find the fenced blocks of a MyST lesson, with their line numbers.

Both the snippet includes and the inline-code check work on the lesson's
text (not on notebook cells) so that every error can name a file and line.
"""
from __future__ import annotations

from dataclasses import dataclass

from markdown_it import MarkdownIt
from mdit_py_plugins.front_matter import front_matter_plugin

_PARSER = MarkdownIt('commonmark').use(front_matter_plugin)


@dataclass(frozen=True)
class Fence:
    """One fenced block. ``start``/``end`` are 0-based line indexes, end exclusive."""

    info: str
    content: str
    start: int
    end: int
    markup: str

    @property
    def directive(self) -> str | None:
        """``snippet`` for ```{snippet}, ``code-cell`` for ```{code-cell}, else None."""
        head = self.info.split(None, 1)[0] if self.info.strip() else ''
        if head.startswith('{') and head.endswith('}'):
            return head[1:-1]
        return None

    @property
    def argument(self) -> str:
        parts = self.info.split(None, 1)
        return parts[1].strip() if len(parts) > 1 else ''

    @property
    def first_content_line(self) -> int:
        """1-based line number of the first line inside the fence."""
        return self.start + 2


def fences(text: str) -> list[Fence]:
    """All top-level and nested fenced blocks of ``text``, in order."""
    return [Fence(tok.info, tok.content, tok.map[0], tok.map[1], tok.markup)
            for tok in _PARSER.parse(text) if tok.type == 'fence' and tok.map]
