"""Snippet includes: code shown in a lesson comes from ``snippets/``, never typed in.

In a markdown part of a lesson, write::

    ```{snippet} my_robot_pkg/launch/sensors.launch.py
    ```

    ```{snippet} my_robot_pkg/setup.py#data_files
    ```

The path is relative to ``snippets/``; ``#name`` selects the lines between
``[START name]`` and ``[END name]`` markers inside the file (in a comment:
``# [START name]`` or ``<!-- [START name] -->``).  Marker lines are never
shown.  The build replaces the directive with a code block in the file's
language under a title with its path (see mkdocs_hook for the title bar).
"""
from __future__ import annotations

import html
import re
import textwrap
from dataclasses import dataclass
from pathlib import Path

from . import paths
from .myst import fences

_MARKER = re.compile(r'^\s*(?:#|//|<!--|;)?\s*\[(START|END) ([\w.-]+)\]\s*(?:-->)?\s*$')

_LANGUAGES = {
    '.py': 'python', '.yaml': 'yaml', '.yml': 'yaml', '.xml': 'xml', '.cfg': 'ini',
    '.ini': 'ini', '.toml': 'toml', '.json': 'json', '.sh': 'bash', '.bash': 'bash',
    '.md': 'markdown', '.txt': 'text', '.cpp': 'cpp', '.hpp': 'cpp', '.h': 'c',
    '.c': 'c', '.urdf': 'xml', '.xacro': 'xml', '.sdf': 'xml', '.rviz': 'yaml',
}


class IncludeError(ValueError):
    """A snippet include names a missing file or section."""


@dataclass(frozen=True)
class Snippet:
    path: Path
    section: str | None
    language: str
    code: str

    @property
    def title(self) -> str:
        return paths.rel(self.path)


def language_of(path: Path) -> str:
    if path.name == 'CMakeLists.txt':
        return 'cmake'
    return _LANGUAGES.get(path.suffix.lower(), 'text')


def _strip_markers(lines: list[str]) -> list[str]:
    return [line for line in lines if not _MARKER.match(line)]


def _section(lines: list[str], name: str) -> list[str] | None:
    """Lines between the START and END markers of ``name`` (None if absent)."""
    start = end = None
    for index, line in enumerate(lines):
        match = _MARKER.match(line)
        if match and match.group(2) == name:
            if match.group(1) == 'START' and start is None:
                start = index
            elif match.group(1) == 'END' and start is not None:
                end = index
                break
    if start is None or end is None:
        return None
    return lines[start + 1:end]


def load_snippet(target: str, where: str = '', root: Path | None = None) -> Snippet:
    """Read ``path[#section]`` (relative to ``root``, snippets/ by default);
    ``where`` prefixes errors."""
    root = (root or paths.SNIPPETS).resolve()
    prefix = f'{where}: ' if where else ''
    relpath, _, section = target.partition('#')
    if not relpath:
        raise IncludeError(f'{prefix}snippet include needs a path under snippets/')
    path = (root / relpath).resolve()
    if not path.is_relative_to(root):
        raise IncludeError(f"{prefix}snippet '{target}' is outside snippets/")
    if not path.is_file():
        raise IncludeError(f'{prefix}snippet file snippets/{relpath} does not exist')
    lines = path.read_text().splitlines()
    if section:
        selected = _section(lines, section)
        if selected is None:
            raise IncludeError(f"{prefix}snippet section '{section}' not found in "
                               f"snippets/{relpath} (mark it with [START {section}] "
                               f"and [END {section}] comments)")
        lines = selected
    code = textwrap.dedent('\n'.join(_strip_markers(lines))).strip('\n')
    return Snippet(path, section or None, language_of(path), code)


def render(snippet: Snippet) -> str:
    """Markdown for one include: a title line and a fenced, highlighted block."""
    longest = max((len(run) for run in re.findall(r'`+', snippet.code)), default=0)
    fence = '`' * max(3, longest + 1)
    return (f'<div class="snippet-title">{html.escape(snippet.title)}</div>\n\n'
            f'{fence}{snippet.language}\n{snippet.code}\n{fence}')


def expand(text: str, source: str, root: Path | None = None) -> tuple[str, list[Snippet]]:
    """Replace every ```{snippet} directive in ``text``; returns the new text and
    the snippets used.  ``source`` (the lesson file) is named in errors."""
    lines = text.splitlines()
    used: list[Snippet] = []
    for fence in reversed(fences(text)):
        if fence.directive != 'snippet':
            continue
        where = f'{source}:{fence.start + 1}'
        if fence.content.strip():
            raise IncludeError(f'{where}: a snippet include takes no content; put the '
                               f'path after {{snippet}} and close the fence')
        snippet = load_snippet(fence.argument, where, root)
        indent = re.match(r'\s*', lines[fence.start]).group(0)
        block = [indent + line if line else line for line in render(snippet).split('\n')]
        lines[fence.start:fence.end] = block
        used.append(snippet)
    used.reverse()
    return '\n'.join(lines) + ('\n' if text.endswith('\n') else ''), used
