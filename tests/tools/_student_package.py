"""A student's package for check tests: only the spec file a check reads."""
from __future__ import annotations

from pathlib import Path

from labkit.grading.student_package import StudentPackage


def with_empty_spec(root: Path, spec: str) -> StudentPackage:
    """A package under ``root`` whose ``spec`` (relative to the package) holds no nodes."""
    path = root / 'src' / 'my_ws_exercises' / spec
    path.parent.mkdir(parents=True)
    path.write_text('nodes: {}\n')
    return StudentPackage(root)
