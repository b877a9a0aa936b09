"""Assistants' drafts (snippets/ai_drafts/) are kept verbatim: a launch file taken
from a reply must be byte for byte the reply's one Python code block."""
from __future__ import annotations

import re
from pathlib import Path


def code_blocks(markdown: str) -> list[str]:
    """The Python code blocks of a Markdown reply, without their fences."""
    return re.findall(r'^```python\n(.*?)^```$', markdown, re.MULTILINE | re.DOTALL)


def assert_draft_is_the_replys_code_block(reply: Path, draft: Path) -> None:
    blocks = code_blocks(reply.read_text())
    assert len(blocks) == 1, f'{reply} should hold exactly one python code block'
    assert draft.read_bytes() == blocks[0].encode(), (
        f'{draft.name} differs from the code block of {reply}: drafts are kept verbatim')
