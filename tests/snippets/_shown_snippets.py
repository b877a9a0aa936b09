"""Which launch files a lesson shows, so tests can require each to be tested."""
from __future__ import annotations

from pathlib import Path

from textbook.myst import fences


def launch_files_included_by(lesson: Path) -> set[tuple[str, str]]:
    """(package, launch file name) of every launch-file snippet the lesson includes."""
    found = set()
    for fence in fences(lesson.read_text()):
        target = fence.argument.partition('#')[0]
        if fence.directive == 'snippet' and target.endswith('.launch.py'):
            package, _, name = target.partition('/launch/')
            found.add((package, name))
    return found
