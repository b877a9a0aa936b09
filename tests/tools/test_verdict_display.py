"""A verdict shows as its ✓/✗ list in a notebook: as text and as HTML (the site).

IPython prefers a __repr__ defined lower in the class tree to a _repr_pretty_,
so a dataclass subclass of Verdict that keeps its generated __repr__ would
show as `ExerciseVerdict(title=..., results=[...])` (it did, on every page).
"""
from __future__ import annotations

from IPython.core.formatters import DisplayFormatter
from labkit.grading.exercise import ExerciseVerdict
from labkit.grading.verdict import Verdict

LIST = '6.1.1 Your first launch file: not solved yet\n  ✓ it builds\n  ✗ no node <b>talker</b>'


def _verdicts() -> list[Verdict]:
    results = [(True, 'it builds'), (False, 'no node <b>talker</b>')]
    return [cls('6.1.1 Your first launch file', list(results))
            for cls in (Verdict, ExerciseVerdict)]


def test_a_notebook_shows_the_list_as_text():
    for verdict in _verdicts():
        shown, _ = DisplayFormatter().format(verdict)
        assert shown['text/plain'] == LIST, type(verdict).__name__


def test_the_site_shows_an_html_list_of_the_same_lines():
    for verdict in _verdicts():
        shown, _ = DisplayFormatter().format(verdict)
        assert shown['text/html'] == (
            '<div class="labkit-verdict"><p>6.1.1 Your first launch file: not solved yet</p>'
            '<ul><li>✓ it builds</li><li>✗ no node &lt;b&gt;talker&lt;/b&gt;</li></ul></div>')


def test_no_verdict_class_brings_its_own_repr():
    subclasses = Verdict.__subclasses__()
    assert ExerciseVerdict in subclasses
    for cls in subclasses:
        assert '__repr__' not in vars(cls), f'{cls.__name__}: use @dataclass(repr=False)'
