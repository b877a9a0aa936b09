"""Reject launch, parameter-file, setup.py and package.xml code typed into a lesson.

Such code must live in ``snippets/``, where it is built, installed and run
by the tests; a lesson shows it with a ```{snippet} include.  The check
reads code cells and fenced code blocks (not prose or `inline code`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from .myst import fences

# (what it is, pattern) - each pattern is a tell-tale line of that kind of file.
RULES: list[tuple[str, re.Pattern[str]]] = [
    ('launch code', re.compile(r'\bLaunchDescription\s*\(')),
    ('launch code', re.compile(r'\bdef\s+generate_launch_description\b')),
    ('an XML launch file', re.compile(r'^\s*<launch[\s>]')),
    ('a YAML launch file', re.compile(r'^\s*launch\s*:\s*$')),
    ('a YAML parameter file', re.compile(r'\bros__parameters\s*:')),
    ('setup.py code', re.compile(r'\bdata_files\s*=')),
    ('setup.py code', re.compile(r'\bentry_points\s*=')),
    ('setup.py code', re.compile(r"['\"]console_scripts['\"]")),
    ('package.xml code', re.compile(r'<package\s+format\s*=')),
    ('package.xml code', re.compile(r'<(?:exec_|build_|buildtool_|test_)?depend>')),
    ('package.xml code', re.compile(r'<build_type>')),
]


@dataclass(frozen=True)
class Violation:
    source: str
    line: int
    kind: str
    text: str

    def __str__(self) -> str:
        return (f'{self.source}:{self.line}: {self.kind} typed into the lesson '
                f'({self.text.strip()!r}); put it in a file under snippets/ and show '
                f'it with a ```{{snippet}} include')


class InlineCodeError(ValueError):
    """A lesson contains code that belongs in snippets/."""


def find_violations(text: str, source: str) -> list[Violation]:
    """Every line of code in ``text`` that belongs in a snippet file."""
    found = []
    for fence in fences(text):
        if fence.directive == 'snippet':
            continue
        for offset, line in enumerate(fence.content.splitlines()):
            for kind, pattern in RULES:
                if pattern.search(line):
                    found.append(Violation(source, fence.first_content_line + offset,
                                           kind, line))
                    break
    return found


def check(text: str, source: str) -> None:
    """Raise InlineCodeError listing every violation in the lesson ``text``."""
    violations = find_violations(text, source)
    if violations:
        raise InlineCodeError('\n'.join(str(v) for v in violations))
