"""The committed record of the lessons whose outputs a real ROS 2 Jazzy printed too.

`python -m textbook parity` writes one entry per lesson whose parity held:
the hash of what the lesson executes (its code cells and the snippets it
uses: `inputs`), the hash of its outputs on the clean room as parity compares
them (`outputs`: normalised, without what the allow-list lets differ), the
day and the Jazzy it was compared with.  An entry stands for the lesson only
while both hashes still match: the lesson and its snippets unchanged, and the
clean room still printing what it printed when the two stacks agreed.  So
the site can say which pages were checked on a real Jazzy, and
`parity --stale` re-runs Jazzy for exactly the lessons that no longer match.
"""
from __future__ import annotations

import datetime
import importlib.util
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import nbformat
import yaml

from . import paths
from .cache import code_text, named_snippets
from .fingerprint import hash_paths, hash_text
from .lessons import Lesson
from .parity_compare import LessonParity, allowances, compared_lines, load_allowed

RECORD = Path(__file__).with_name('parity_record.yaml')
_HEADER = """\
# Lessons whose outputs were the same on a real ROS 2 Jazzy, written by
# `python -m textbook parity` (tools/textbook/parity_record.py): never by hand.
# An entry counts while `inputs` (the lesson's code cells and snippets) and
# `outputs` (its clean-room outputs as parity compares them) still match.
"""


def inputs_hash(lesson: Lesson) -> str:
    """What the lesson executes, whatever runs it: its code cells and the snippets
    it names.  (Not all of snippets/, as the cache takes for a lesson that builds
    the workspace: a package the lesson never names changes its outputs at most,
    and the outputs hash sees that; one snippet edit must not send every lesson
    back to Jazzy.)"""
    return hash_text(code_text(lesson),
                     hash_paths(named_snippets(lesson), base=paths.SNIPPETS.parent))


def outputs_hash(lesson: Lesson, notebook: nbformat.NotebookNode,
                 allowed: list[dict] | None = None) -> str:
    """The executed `notebook`'s outputs as parity compares them; a cell the
    allow-list lets differ as a whole counts only as a cell."""
    allowed = load_allowed() if allowed is None else allowed
    parts = []
    for cell in notebook.cells:
        if cell.cell_type != 'code':
            continue
        entries = allowances(lesson.id, cell.source, allowed)
        whole = any('lines' not in entry for entry in entries)
        parts.append('(differs by the allow-list)' if whole
                     else '\n'.join(compared_lines(cell, entries)))
    return hash_text(*parts)


@dataclass(frozen=True)
class Status:
    """Whether a lesson's outputs, as they are now, were seen on a real Jazzy."""

    held: bool
    checked: str = ''  # the day parity held
    reference: str = ''  # the Jazzy it was compared with


def load(path: Path = RECORD) -> dict[str, dict]:
    return (yaml.safe_load(path.read_text()) or {}) if path.exists() else {}


def status(lesson: Lesson, notebook: nbformat.NotebookNode,
           record: Mapping[str, dict] | None = None) -> Status:
    """The record's word on `lesson` executed as `notebook`."""
    entry = (load() if record is None else record).get(lesson.id)
    if (entry is None or entry.get('inputs') != inputs_hash(lesson)
            or entry.get('outputs') != outputs_hash(lesson, notebook)):
        return Status(held=False)
    return Status(held=True, checked=str(entry['checked']), reference=entry['reference'])


def update(results: list[tuple[Lesson, LessonParity, nbformat.NotebookNode | None]],
           reference: str, path: Path = RECORD) -> None:
    """Record each lesson that held (with its clean-room notebook) and forget each
    that did not; other lessons' entries stay as they were."""
    record = load(path)
    today = datetime.date.today().isoformat()
    for lesson, parity, notebook in results:
        if parity.held and notebook is not None:
            record[lesson.id] = {'inputs': inputs_hash(lesson),
                                 'outputs': outputs_hash(lesson, notebook),
                                 'checked': today, 'reference': reference}
        else:
            record.pop(lesson.id, None)
    body = yaml.safe_dump(dict(sorted(record.items())), sort_keys=True, width=100)
    path.write_text(_HEADER + body)


def on_clean_room() -> bool:
    """Whether this environment's `launch` is the book's clean room."""
    spec = importlib.util.find_spec('launch')
    origin = Path(spec.origin) if spec and spec.origin else None
    return origin is not None and origin.is_relative_to(paths.TOOLS / 'cleanroom')


def provenance(lesson: Lesson, notebook: nbformat.NotebookNode,
               record: Mapping[str, dict] | None = None) -> str:
    """One sentence for the page: which stack executed it and, on the clean room,
    whether a real Jazzy printed the same."""
    if not on_clean_room():
        return 'executed on a real ROS 2 Jazzy.'
    said = status(lesson, notebook, record)
    stack = ("executed on the book's headless stack (ROS 2 Jazzy's rclpy and messages, "
             "the book's clean-room launch and ros2)")
    if said.held:
        return f'{stack}; a real ROS 2 Jazzy ({said.reference}) printed the same, ' \
               f'compared on {said.checked}.'
    return f'{stack}; not compared with a real ROS 2 Jazzy since the lesson or the ' \
           f'clean room last changed.'
