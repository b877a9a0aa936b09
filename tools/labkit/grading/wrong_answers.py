"""Wrong answers of an exercise, kept as patches against its solution.

`snippets/<solutions>/wrong/<exercise id>/<name>.patch` is a header, then a
unified diff whose paths are inside the package::

    # Mistake: the filter node is missing
    #   (a line that goes on starts with '#   ')
    # Verdict names: /sensor_filter is not in the graph
    --- a/launch/ex61_full_pipeline.launch.py
    +++ b/launch/ex61_full_pipeline.launch.py
    @@ -12,7 +12,6 @@
     ...

The wrong answer is the solution with the patch applied.  Patches are
applied strictly (no offset, no fuzz): a context or removed line that no
longer matches the solution raises PatchError naming the patch file and
the line of its hunk, so a solution that changed under a wrong answer fails
loudly instead of grading something else.

`make` writes one from an edited copy of the solutions package (the command:
labkit.grading.make_wrong_answer).
"""
from __future__ import annotations

import difflib
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

MISTAKE = '# Mistake'
GOES_ON = '#   '
VERDICT_NAMES = '# Verdict names: '
NO_NEWLINE = '\\ No newline at end of file'
_HUNK = re.compile(r'^@@ -(\d+)(?:,(\d+))? \+(\d+)(?:,(\d+))? @@')


class PatchError(ValueError):
    """A patch file that is malformed or no longer applies to the solution."""


@dataclass(frozen=True)
class Hunk:
    line: int  # of the '@@' line in the patch file
    old_start: int
    old_count: int
    new_count: int
    lines: tuple[str, ...]  # each with its ' ', '-' or '+', and its own line end
    numbers: tuple[int, ...]  # of each of `lines` in the patch file


@dataclass(frozen=True)
class FilePatch:
    line: int  # of the '---' line in the patch file
    path: str  # inside the package
    created: bool  # '--- /dev/null': the solution has no such file
    hunks: tuple[Hunk, ...]


@dataclass(frozen=True)
class WrongAnswer:
    path: Path
    mistake: str
    verdict_names: tuple[str, ...]
    files: tuple[FilePatch, ...]

    def apply(self, solution: Callable[[str], str]) -> dict[str, str]:
        """{path inside the package: patched text} of every file the patch
        touches; `solution(path)` gives the solution's text of a file."""
        return {f.path: _apply_file(self.path, f, '' if f.created else solution(f.path))
                for f in self.files}


def read(path: Path) -> WrongAnswer:
    """Parse a patch file; PatchError names the file and line of what is wrong."""
    lines = path.read_text().splitlines(keepends=True)
    mistake: list[str] = []
    verdict_names: list[str] = []
    number = 0
    while number < len(lines) and lines[number].startswith('#'):
        text = lines[number].rstrip('\n')
        if text.startswith(MISTAKE):
            mistake.append(text.removeprefix('#').strip())
        elif text.startswith(VERDICT_NAMES):
            verdict_names.append(text.removeprefix(VERDICT_NAMES).strip())
        elif text.startswith(GOES_ON) and mistake:
            mistake[-1] += ' ' + text.removeprefix(GOES_ON).strip()
        else:
            raise PatchError(f'{path}:{number + 1}: a header line is "# Mistake...", '
                             f'"#   " (goes on) or "{VERDICT_NAMES}...", not {text!r}')
        number += 1
    if not mistake or not verdict_names:
        raise PatchError(f'{path}: the header needs a "# Mistake: ..." and a '
                         f'"{VERDICT_NAMES}..." line')
    files = []
    while number < len(lines):
        file, number = _read_file(path, lines, number)
        files.append(file)
    if not files:
        raise PatchError(f'{path}: no "--- a/<file>" / "+++ b/<file>" diff after the header')
    return WrongAnswer(path, '\n'.join(mistake), tuple(verdict_names), tuple(files))


def _read_file(path: Path, lines: list[str], number: int) -> tuple[FilePatch, int]:
    start = number
    old, new = (lines[number:number + 2] + ['', ''])[:2]
    if not old.startswith('--- ') or not new.startswith('+++ '):
        raise PatchError(f'{path}:{number + 1}: expected "--- a/<file>" then "+++ b/<file>", '
                         f'found {old.rstrip()!r}')
    old_name, new_name = old[4:].split('\t')[0].strip(), new[4:].split('\t')[0].strip()
    if not new_name.startswith('b/'):
        raise PatchError(f'{path}:{number + 2}: "+++ b/<file>" expected (deleting a file '
                         f'is not supported), found {new.rstrip()!r}')
    created = old_name == '/dev/null'
    if not created and old_name[2:] != new_name[2:]:
        raise PatchError(f'{path}:{number + 1}: {old_name} and {new_name} name different files')
    number += 2
    hunks = []
    while number < len(lines) and lines[number].startswith('@@'):
        hunk, number = _read_hunk(path, lines, number)
        hunks.append(hunk)
    if not hunks:
        raise PatchError(f'{path}:{number + 1}: no "@@ ... @@" hunk for {new_name}')
    return FilePatch(start + 1, new_name[2:], created, tuple(hunks)), number


def _read_hunk(path: Path, lines: list[str], number: int) -> tuple[Hunk, int]:
    match = _HUNK.match(lines[number])
    if not match:
        raise PatchError(f'{path}:{number + 1}: malformed hunk header {lines[number].rstrip()!r}')
    old_start, old_count, _, new_count = (int(g) if g is not None else 1 for g in match.groups())
    start = number
    body: list[str] = []
    numbers: list[int] = []
    old_seen = new_seen = 0
    number += 1
    while (old_seen < old_count or new_seen < new_count
           or number < len(lines) and lines[number].startswith(NO_NEWLINE)):
        if number >= len(lines):
            raise PatchError(f'{path}:{start + 1}: the hunk ends before its '
                             f'{old_count} old and {new_count} new lines')
        line = lines[number]
        if line.startswith(NO_NEWLINE):
            if not body:
                raise PatchError(f'{path}:{number + 1}: "{NO_NEWLINE}" before any line')
            body[-1] = body[-1].removesuffix('\n')
        elif line[:1] in (' ', '-', '+'):
            old_seen += line[0] in ' -'
            new_seen += line[0] in ' +'
            body.append(line)
            numbers.append(number + 1)
        elif line == '\n':  # an empty context line whose blank an editor dropped
            old_seen += 1
            new_seen += 1
            body.append(' \n')
            numbers.append(number + 1)
        else:
            raise PatchError(f'{path}:{number + 1}: a hunk line starts with " ", "-" or "+", '
                             f'not {line.rstrip()!r}')
        number += 1
    if old_seen != old_count or new_seen != new_count:
        raise PatchError(f'{path}:{start + 1}: the hunk has {old_seen} old and {new_seen} new '
                         f'lines, its header says {old_count} and {new_count}')
    return Hunk(start + 1, old_start, old_count, new_count, tuple(body), tuple(numbers)), number


def _apply_file(path: Path, file: FilePatch, text: str) -> str:
    original = text.splitlines(keepends=True)
    result: list[str] = []
    done = 0  # lines of the original already copied or replaced
    for hunk in file.hunks:
        # '@@ -0,0' (a new or empty file) starts before line 1, like '@@ -1,N'
        first = hunk.old_start - 1 if hunk.old_count else hunk.old_start
        if first < done:
            raise PatchError(f'{path}:{hunk.line}: the hunk for {file.path} starts at line '
                             f'{hunk.old_start}, before the end of the hunk above it')
        result += original[done:first]
        at = first
        for line, number in zip(hunk.lines, hunk.numbers, strict=True):
            if line[0] in ' -':
                if at >= len(original) or original[at] != line[1:]:
                    found = (repr(original[at].rstrip('\n')) if at < len(original)
                             else 'no more lines')
                    raise PatchError(
                        f'{path}:{number}: the hunk of line {hunk.line} does not apply to '
                        f'{file.path}: line {at + 1} should be {line[1:].rstrip(chr(10))!r}, '
                        f'the solution has {found} (the solution changed: make the patch again)')
                at += 1
            if line[0] in ' +':
                result.append(line[1:])
        done = at
    return ''.join(result + original[done:])


def diff(relative: str, solution: str | None, wrong: str) -> str:
    """The unified diff of one file, '' when it does not differ from the solution."""
    if solution == wrong:
        return ''
    lines = list(difflib.unified_diff(
        (solution or '').splitlines(keepends=True), wrong.splitlines(keepends=True),
        '/dev/null' if solution is None else f'a/{relative}', f'b/{relative}'))
    return ''.join(line if line.endswith('\n') else f'{line}\n{NO_NEWLINE}\n' for line in lines)


def header(mistake: str, verdict_names: Sequence[str]) -> str:
    """The '# Mistake: ...' and '# Verdict names: ...' lines of a patch file."""
    first, *more = mistake.splitlines()
    lines = [first if first.startswith(MISTAKE) else f'{MISTAKE}: {first}']
    lines += [f'{GOES_ON}{line}' for line in more]
    lines += [f'{VERDICT_NAMES}{phrase}' for phrase in verdict_names]
    return ''.join(f'{line}\n' for line in lines)


def make(solutions: Path, edited: Path, mistake: str, verdict_names: Sequence[str]) -> str:
    """A patch file's text: `edited`, a copy of the `solutions` package with the
    mistake made, against the solution (files equal to the solution are left out)."""
    parts = []
    for file in sorted(f for f in edited.rglob('*') if f.is_file()):
        relative = file.relative_to(edited)
        if relative.parts[0] == 'wrong' or '__pycache__' in relative.parts:
            continue
        solution = solutions / relative
        parts.append(diff(relative.as_posix(),
                          solution.read_text() if solution.is_file() else None, file.read_text()))
    if not any(parts):
        raise PatchError(f'{edited}: no file differs from {solutions}')
    return header(mistake, verdict_names) + ''.join(parts)
