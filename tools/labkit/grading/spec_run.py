"""One run of the spec checker (`speccheck`) in a student's workspace,
as the checks of the spec lessons (6.8, 6.14, 7.1) grade with it.

speccheck live waits 20 s for the spec's nodes.  On a busy machine a system
with three robots can take longer to start them, and a wait that ran out on
nodes the system does run says nothing about the spec: `run_live` repeats
such a run with a longer wait, and says in `SpecRun.unjudged` when the system
never came up, so that it is never taken for a defect the spec caught.
"""
from __future__ import annotations

import dataclasses
import re
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from labkit.grading.student_package import StudentPackage

#: The `speccheck` command next to this interpreter, as a student runs it (else the module).
_COMMAND = Path(sys.executable).with_name('speccheck')
SPECCHECK = [str(_COMMAND)] if _COMMAND.is_file() else [sys.executable, '-m', 'speccheck']
#: Seconds; only stops a hung run, never a speed limit.
SPEC_TIMEOUT = 180.0
#: speccheck's finding when the launch's nodes did not all appear in time (labkit's words)
NOT_STARTED = re.compile(
    r'^launch: Timed out after (?P<seconds>[\d.]+) s waiting for nodes? (?P<nodes>.+?) from `')
#: Seconds to wait for a system's nodes when speccheck's 20 s ran out on nodes it runs.
SLOW_START = 120
SHOWN_LINES = 6


@dataclass(frozen=True)
class SpecRun:
    """The command as a student would type it, its exit code and what it printed."""

    command: str
    returncode: int
    stdout: str
    stderr: str
    #: why the spec was not judged (the system never started nodes it runs), or ''
    unjudged: str = ''

    @property
    def failed(self) -> list[str]:
        """The findings marked FAILED, without the marker."""
        return [line.strip().removeprefix('FAILED').strip()
                for line in self.stdout.splitlines() if line.startswith('  FAILED')]

    @property
    def not_started(self) -> list[str]:
        """The nodes the launch had not started when speccheck stopped waiting, if
        that is a finding of this run (it waits `--timeout` seconds, 20 by default)."""
        match = self._not_started()
        return match['nodes'].split(', ') if match else []

    def _not_started(self) -> re.Match[str] | None:
        return next(filter(None, map(NOT_STARTED.match, self.failed)), None)

    def _still_starting(self, runs: Callable[[str], bool]) -> bool:
        """Whether the wait ran out on nodes that the system does run (`runs(name)`):
        then this run says nothing about the spec."""
        return bool(self.not_started) and all(runs(node) for node in self.not_started)

    def _not_judged(self, system: str) -> str:
        """Why the spec was not judged on `system`, with what speccheck saw of it."""
        match = self._not_started()
        assert match, '_not_judged is for a run whose wait ran out'
        lines = self.stdout.strip().splitlines()
        start = next(i for i, line in enumerate(lines) if line.startswith('  FAILED'))
        below = lines[start + 1:-1]  # the finding's last lines, above the summary
        seen = [line for line in below if line.startswith('Nodes in the graph')]
        return (f'`{self.command}` did not start {match["nodes"]} within {match["seconds"]} s, '
                f'so your spec was not judged on {system}: run the check again when the '
                'machine is less busy. It reported:\n      '
                + '\n      '.join([*seen, *below[-SHOWN_LINES:]]))

    def shown_findings(self, count: int = SHOWN_LINES) -> str:
        """The first `count` findings, one per line, for a verdict; a run that failed
        without a finding (a crash, a signal) shows its exit code and last lines instead,
        so a verdict never quotes an empty report."""
        if self.failed:
            return '\n      '.join(self.failed[:count])
        last = (self.stdout + self.stderr).strip().splitlines()[-count:]
        return '\n      '.join([f'(exit code {self.returncode}, no finding; its last lines:)',
                                 *last])

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
    """`speccheck MODE SPEC TARGET...` in the student's workspace, with the
    environment of its sourced install (or `env`); `shown` is the command to print."""
    done = subprocess.run([*SPECCHECK, mode, str(spec), *target],
                          env=package.environment() if env is None else env,
                          cwd=package.workspace, capture_output=True, text=True,
                          timeout=SPEC_TIMEOUT, check=False)
    return SpecRun(shown, done.returncode, done.stdout, done.stderr)


def run_live(package: StudentPackage, spec: Path, target: list[str],
             command: Callable[[list[str]], str], runs: Callable[[str], bool],
             system: str) -> SpecRun:
    """`speccheck live SPEC TARGET...` (`command(target)` is what a student
    types); once more with `--timeout SLOW_START` when the first run's wait ran out on
    nodes the system runs (`runs(name)`), and `unjudged` set when that one's did too
    (`system` names the system to the student)."""
    run = run_speccheck(package, 'live', spec, target, command(target))
    if not run._still_starting(runs):
        return run
    longer = ['--timeout', str(SLOW_START), *target]
    run = run_speccheck(package, 'live', spec, longer, command(longer))
    if run._still_starting(runs):
        return dataclasses.replace(run, unjudged=run._not_judged(system))
    return run
