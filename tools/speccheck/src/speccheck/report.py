"""The result of a check: one finding per requirement, met or not, with evidence.

A Report prints as plain text (command line, `assert report.ok, report`),
and as a table in a notebook (`_repr_markdown_` / `_repr_html_`).
"""
from __future__ import annotations

import html
from dataclasses import dataclass, replace
from enum import Enum

from speccheck import codes
from speccheck.yaml_lines import LineMap, line_of


class Status(Enum):
    MET = 'met'
    FAILED = 'FAILED'
    #: Cannot be known from here (e.g. what an OpaqueFunction does, before it runs).
    NOT_CHECKED = 'not checked'


_MARKS = {Status.MET: '✓', Status.FAILED: '✗', Status.NOT_CHECKED: '?'}


@dataclass(frozen=True)
class Finding:
    """One requirement (e.g. `topic /distance: publisher /sensor_publisher`) and what was found.

    `code` (speccheck.codes) says what kind of requirement failed, `at` is the
    spec's path of the requirement (('nodes', '/a') ...; () for the launch file
    as a whole) and `line` its line in the spec file, filled in by
    :func:`located`.  They appear in the JSON, JUnit and SARIF reports, never in
    the text one, which lessons print.
    """

    requirement: str
    status: Status
    evidence: str
    code: str | None = None
    at: tuple = ()
    line: int | None = None

    def __str__(self) -> str:
        return f'{self.status.value:<11} {self.requirement}: {self.evidence}'

    @property
    def rule(self) -> str | None:
        """The finding's code; NotChecked for an undecided one without its own."""
        if self.code is None and self.status is Status.NOT_CHECKED:
            return codes.NOT_CHECKED
        return self.code

    @property
    def hint(self) -> str:
        """One line on how to fix it ('' for a met requirement)."""
        return codes.HINTS.get(self.rule, '') if self.status is not Status.MET else ''


def located(findings: list[Finding], lines: LineMap) -> tuple[Finding, ...]:
    """`findings` with the spec line of each one's `at` (the file's first line for ())."""
    return tuple(replace(f, line=line_of(lines, f.at) or 1) for f in findings)


@dataclass(frozen=True, repr=False)
class Report:
    """All findings of one check (`kind` is 'static' or 'live')."""

    kind: str
    spec: str
    target: str
    findings: tuple[Finding, ...]

    @property
    def ok(self) -> bool:
        """True when no requirement failed (unchecked ones do not count as failures)."""
        return not self.failures

    @property
    def failures(self) -> list[Finding]:
        return [f for f in self.findings if f.status is Status.FAILED]

    @property
    def exit_code(self) -> int:
        """0 every requirement met, 1 some requirement not met (2, could not judge, is
        the command line's: a spec, launch file or argument it cannot use)."""
        return 0 if self.ok else 1

    def find(self, requirement: str) -> list[Finding]:
        """Findings whose requirement starts with `requirement` (e.g. 'topic /distance')."""
        return [f for f in self.findings if f.requirement.startswith(requirement)]

    def summary(self) -> str:
        counts = {status: 0 for status in Status}
        for finding in self.findings:
            counts[finding.status] += 1
        verdict = 'PASSED' if self.ok else 'FAILED'
        return (f'{verdict}: {counts[Status.MET]} met, {counts[Status.FAILED]} failed, '
                f'{counts[Status.NOT_CHECKED]} not checked')

    def title(self) -> str:
        return f'speccheck {self.kind}: {self.target} against {self.spec}'

    def __str__(self) -> str:
        return '\n'.join([self.title(), *(f'  {f}' for f in self.findings), self.summary()])

    def __repr__(self) -> str:
        """The verdict and the failures first: pytest shows this (shortened) for
        `assert report.ok, report`; use `report.assert_ok()` for every line."""
        failed = '; '.join(f'{f.requirement}: {f.evidence}' for f in self.failures)
        return f'<speccheck {self.kind} {self.summary()}{"; " + failed if failed else ""}>'

    def assert_ok(self) -> None:
        """Raise AssertionError with the whole report when a requirement failed."""
        if not self.ok:
            raise AssertionError(str(self))

    def _repr_pretty_(self, printer, cycle: bool) -> None:  # IPython plain text
        printer.text(str(self))

    def _repr_markdown_(self) -> str:
        rows = [f'| {_MARKS[f.status]} {f.status.value} | {_md(f.requirement)} | '
                f'{_md(f.evidence)} |' for f in self.findings]
        return '\n'.join([f'**{_md(self.title())}**', '', '| | requirement | evidence |',
                          '| --- | --- | --- |', *rows, '', f'**{self.summary()}**'])

    def _repr_html_(self) -> str:
        colours = {Status.MET: '#1a7f37', Status.FAILED: '#cf222e',
                   Status.NOT_CHECKED: '#9a6700'}
        rows = ''.join(
            f'<tr><td style="color:{colours[f.status]};white-space:nowrap">'
            f'{_MARKS[f.status]} {f.status.value}</td><td><code>{html.escape(f.requirement)}'
            f'</code></td><td>{html.escape(f.evidence)}</td></tr>' for f in self.findings)
        return (f'<div class="speccheck-report"><p><b>{html.escape(self.title())}</b></p>'
                '<table><thead><tr><th></th><th>requirement</th><th>evidence</th></tr></thead>'
                f'<tbody>{rows}</tbody></table><p><b>{html.escape(self.summary())}</b></p></div>')


def _md(text: str) -> str:
    return text.replace('|', '\\|').replace('\n', ' ')
