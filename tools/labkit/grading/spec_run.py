"""One run of the spec checker (`python -m speccheck`) in a student's workspace,
as the checks of the spec lessons (6.8, 6.14, 7.1) grade with it."""
from __future__ import annotations

import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from labkit.grading.student_package import StudentPackage

#: Seconds; only stops a hung run, never a speed limit.
SPEC_TIMEOUT = 180.0


@dataclass(frozen=True)
class SpecRun:
    """The command as a student would type it, its exit code and what it printed."""

    command: str
    returncode: int
    stdout: str
    stderr: str

    @property
    def failed(self) -> list[str]:
        """The findings marked FAILED, without the marker."""
        return [line.strip().removeprefix('FAILED').strip()
                for line in self.stdout.splitlines() if line.startswith('  FAILED')]

    @property
    def error(self) -> str:
        """speccheck's own error message (bad spec or launch file), exit code 2."""
        return self.stderr.strip() or self.stdout.strip()

    @property
    def summary(self) -> str:
        """speccheck's last line (its counts)."""
        lines = self.stdout.strip().splitlines()
        return lines[-1] if lines else ''


def run_speccheck(package: StudentPackage, mode: str, spec: Path, target: list[str],
                  shown: str, env: dict[str, str] | None = None) -> SpecRun:
    """`python -m speccheck MODE SPEC TARGET...` in the student's workspace, with the
    environment of its sourced install (or `env`); `shown` is the command to print."""
    done = subprocess.run([sys.executable, '-m', 'speccheck', mode, str(spec), *target],
                          env=package.environment() if env is None else env,
                          cwd=package.workspace, capture_output=True, text=True,
                          timeout=SPEC_TIMEOUT, check=False)
    return SpecRun(shown, done.returncode, done.stdout, done.stderr)
