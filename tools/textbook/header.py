"""The box at the top of a lesson page, made from its ``textbook:`` metadata.

A student sees before reading what the lesson teaches, how long it takes,
its level, the hardware it needs (and how to follow it on a laptop), which
lessons come first, linked, and what produced the outputs shown.
"""
from __future__ import annotations

from html import escape
from typing import Any

from .metadata import HARDWARE_TIERS


def header_html(meta: dict[str, Any], prerequisites: list[tuple[str, str]],
                outputs: str = '') -> str:
    """The header box; ``prerequisites`` are (title, url) of the lessons to read first,
    ``outputs`` says what produced the page's outputs (`parity_record.provenance`)."""
    tier = meta['hardware_tier']
    facts = (f'<span class="textbook-fact"><strong>Duration</strong> '
             f'{meta["duration_minutes"]} min</span> '
             f'<span class="textbook-fact"><strong>Level</strong> '
             f'{escape(meta["proficiency"])}</span> '
             f'<span class="textbook-fact"><strong>Hardware</strong> '
             f'tier {tier} ({escape(HARDWARE_TIERS[tier])})</span>')
    objectives = ''.join(f'<li>{escape(item)}</li>' for item in meta['learning_objectives'])
    if prerequisites:
        before = ', '.join(f'<a href="{escape(url)}">{escape(title)}</a>'
                           for title, url in prerequisites)
    else:
        before = 'nothing: start here'
    return (f'<div class="admonition info textbook-header">'
            f'<p class="admonition-title">About this lesson</p>'
            f'<p class="textbook-facts">{facts}</p>'
            f'<p><strong>You will learn to</strong></p><ul>{objectives}</ul>'
            f'<p class="textbook-tier-1"><strong>On a laptop (tier 1):</strong> '
            f'{escape(meta["tier_1_path"].strip())}</p>'
            f'<p class="textbook-prerequisites"><strong>Before this lesson:</strong> '
            f'{before}</p>'
            + (f'<p class="textbook-outputs"><strong>Outputs on this page:</strong> '
               f'{escape(outputs)}</p>' if outputs else '')
            + '</div>')
