"""What a check found: each requirement met or not, in words a student can act on."""
from __future__ import annotations

import html
from dataclasses import dataclass, field

from labkit.errors import LabkitError


class ExerciseNotSolved(LabkitError):
    """A check found unmet requirements (raised in the book's build, where the
    solution was applied and must pass)."""


@dataclass
class Verdict:
    """The result of one check: a list of (met, sentence) pairs."""

    title: str
    results: list[tuple[bool, str]] = field(default_factory=list)

    def expect(self, met: bool, when_met: str, when_not: str) -> bool:
        """Record one requirement; `when_not` must say what is wrong and what to do."""
        self.results.append((bool(met), when_met if met else when_not))
        return bool(met)

    def fail(self, reason: str) -> Verdict:
        """Record a problem that stops the check (nothing further can be judged)."""
        self.results.append((False, reason))
        return self

    @property
    def passed(self) -> bool:
        return bool(self.results) and all(met for met, _ in self.results)

    @property
    def problems(self) -> list[str]:
        return [sentence for met, sentence in self.results if not met]

    def __str__(self) -> str:
        head = f'{self.title}: ' + ('solved' if self.passed else 'not solved yet')
        lines = [f'  {"✓" if met else "✗"} {sentence}' for met, sentence in self.results]
        return '\n'.join([head, *lines])

    # How a notebook shows a verdict: as the ✓/✗ list of str(), in Jupyter's
    # text form and, on the site and in JupyterLab, as an HTML list.  A subclass
    # must be a @dataclass(repr=False): IPython prefers a __repr__ defined
    # lower in the class tree to this _repr_pretty_.
    def _repr_pretty_(self, printer: object, cycle: bool) -> None:  # IPython display
        printer.text(str(self))  # type: ignore[attr-defined]

    def _repr_html_(self) -> str:
        head, *lines = str(self).splitlines()
        items = ''.join(f'<li>{html.escape(line.strip())}</li>' for line in lines)
        return (f'<div class="labkit-verdict"><p>{html.escape(head)}</p>'
                f'<ul>{items}</ul></div>')
