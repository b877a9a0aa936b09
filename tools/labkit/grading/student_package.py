"""The student's package in their workspace: where its files are, whether the
installed copy is current, and the environment of `source install/setup.bash`."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from labkit.workspace import sourced_environment

#: The package every exercise of the book is written in.
PACKAGE = 'my_ws_exercises'


@dataclass(frozen=True)
class StudentPackage:
    """`workspace/src/<name>/`, built into `workspace/install/<name>/`."""

    workspace: Path
    name: str = PACKAGE

    @property
    def source(self) -> Path:
        return self.workspace / 'src' / self.name

    @property
    def share(self) -> Path:
        return self.workspace / 'install' / self.name / 'share' / self.name

    def shown(self, path: Path) -> str:
        """`path` relative to the workspace, as a student sees it in a terminal."""
        try:
            return str(path.relative_to(self.workspace))
        except ValueError:
            return str(path)

    def installed_problem(self, relative: str) -> str | None:
        """Why `relative` (e.g. 'launch/x.launch.py') is not ready to run, or None.

        Compares contents, not times: after `colcon build` the installed copy
        equals the source (or links to it with --symlink-install).
        """
        source, installed = self.source / relative, self.share / relative
        if not source.is_file():
            return (f'{self.shown(source)} does not exist: run '
                    f'labkit.exercises.setup() to create the starter files')
        if not installed.is_file():
            return (f'{self.shown(source)} is not installed (no {self.shown(installed)}): '
                    f'run colcon build --packages-select {self.name}')
        if source.read_bytes() != installed.read_bytes():
            return (f'{self.shown(source)} is newer than the installed copy: '
                    f'run colcon build --packages-select {self.name}')
        return None

    def environment(self, base: dict[str, str] | None = None) -> dict[str, str]:
        """`base` (default: this process's) after `source install/setup.bash`,
        done by bash itself, as in the student's terminal."""
        return sourced_environment(self.workspace, base)
