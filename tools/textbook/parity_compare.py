"""What parity compares: a code cell's outputs on two stacks, normalised.

Only what varies from run to run (pids, times, temporary paths, domain ids,
the order in which launch interleaves its processes' lines) or between two
installs of the same ROS 2 (where its Python lives) is normalised; the
allow-list (parity_allowed.yaml) names the few differences that stay, each
with its reason.
"""
from __future__ import annotations

import difflib
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import nbformat
import yaml

from . import paths

JAZZY_BUILD = paths.ROOT / 'build' / 'jazzy'
ALLOWED = Path(__file__).with_name('parity_allowed.yaml')


# -- normalising ----------------------------------------------------------------
#: (pattern, replacement): what differs between two runs of the same lesson on
#: one machine, whatever the stack.  Nothing else is touched.
_VARYING = [
    (re.compile(r'\bpid \[\d+\]'), 'pid [PID]'),
    (re.compile(r'\bpid \d+'), 'pid PID'),
    (re.compile(r'0x[0-9a-f]{6,}'), '0x…'),
    (re.compile(r'\d{4}-\d\d-\d\d-\d\d-\d\d-\d\d-\d+-[\w.-]+?-\d+'), 'LOG-DIR'),
    (re.compile(r'\[\d{9,}\.\d+\]'), '[TIME]'),
    (re.compile(r'launch_params_\w+'), 'launch_params_…'),
    # a file of tempfile.mkstemp(prefix='robot_controller_params_', suffix='.yaml')
    (re.compile(r'(?<=_params_)[a-z0-9_]{8}(?=\.yaml\b)'), '…'),
    (re.compile(r'ROS_DOMAIN_ID=\d+'), 'ROS_DOMAIN_ID=…'),
    # colcon's durations: `[3.04s]`, `[2min 55s]`, a log line's `[0.797s]`
    (re.compile(r'\[(\d+min )?\d+(\.\d+)?s\]'), '[…s]'),
    (re.compile(re.escape(str(paths.RUNS)) + r'/[\w.-]+'), '~/ros2_ws'),
    (re.compile(r'\bprocess ID \d+'), 'process ID PID'),
    # a folder of tempfile.mkdtemp(prefix=...): /tmp/ex64_qe1ov5gk
    (re.compile(r'(/tmp/(?:tmp|[\w-]+_))[a-z0-9_]{8}\b'), r'\1…'),
    (re.compile(r"\bdomain ID of '\d+'"), "domain ID of '…'"),
    # launch.log's lines start with the time in seconds
    (re.compile(r'^\d{9,}\.\d+ ', re.M), ''),
    # a node's log file: ~/.ros/log/<executable>_<pid>_<milliseconds>.log
    (re.compile(r'_\d+_\d{13}\.log\b'), '_PID_TIME.log'),
    # how long tests took: unittest's `Ran 3 tests in 1.198s`, pytest's last line
    # `1 passed, 2 deselected in 2.51s` (with or without its `=` rule)
    (re.compile(r'^(Ran \d+ tests? in )\d+\.\d+s$', re.M), r'\1…s'),
    (re.compile(r'^(=* ?\d+ (?:passed|failed|error|errors|skipped|deselected)\b.* in )'
                r'\d+\.\d+s(?: \(\d+:\d\d:\d\d\))?( ?=*)$', re.M), r'\1…s\2'),
    # the launch process's own node carries its pid: `/launch_ros_11575`
    (re.compile(r'\blaunch_ros_\d+'), 'launch_ros_PID'),
    # ros2cli's hidden node carries the pid of the command: `_ros2cli_20479`
    (re.compile(r'\b_ros2cli_\d+'), '_ros2cli_PID'),
    # an endpoint's GID is made up when the endpoint is created
    (re.compile(r'\bGID: [0-9a-f.]+'), 'GID: …'),
]
#: What differs between two installs of ROS 2 Jazzy, not between the stacks' behaviour:
#: where the Python that runs Python nodes lives (`/usr/bin/python3` on Ubuntu, a venv
#: or pyenv here), and so where its packages are (a traceback's file names).
_INSTALL = [
    (re.compile(r'(?<![\w/.~])~?/[\w./-]*/bin/python3?(?:\.\d+)?(?=\s|$)', re.M), 'python3'),
    (re.compile(r'(?<![\w/.~])~?/[\w./-]*/lib/python3\.\d+/site-packages/'), 'site-packages/'),
    # the log file of a Python node is named after the interpreter (python, python3.12)
    (re.compile(r'\bpython3?(?:\.\d+)?(?=_PID_TIME\.log)'), 'python3'),
]
#: A line of a launched process (`[talker-1] ...`, group 2) or launch's line about
#: it (`[INFO] [talker-1]: process started with pid [...]`, group 1).
_PROCESS_LINE = re.compile(r'^(?:\[(?:DEBUG|INFO|WARN|WARNING|ERROR|FATAL)\] \[([\w.-]+-\d+)\]:'
                           r'|\[([\w.-]+-\d+)\] )')
#: A line an event handler's LogInfo printed, e.g. on a process's output or exit.
_HANDLER_LINE = re.compile(r'^\[(?:INFO|WARNING|ERROR)\] \[launch\.user\]: ')


def normalise(text: str, builds: Iterable[Path] = ()) -> list[str]:
    """The lines of `text` with run-to-run variation replaced by placeholders.

    `builds` are build folders that stand for each other (build/jazzy and
    build).  A run of consecutive lines about launched processes is put in
    an order launch itself defines: process by process (by name), launch's
    own lines about the process (started, finished, died) in their order,
    then what the process printed, in its order; the lines of event
    handlers (`launch.user`) last, sorted.  Launch starts the processes of
    one description at once, reads their output while it watches them exit,
    and runs handlers as events come: how these interleave is up to the
    operating system, on either stack.
    """
    for build in builds:
        text = text.replace(str(build), str(paths.ROOT / 'build'))
        text = text.replace(paths.shown(str(build)),
                            paths.shown(str(paths.ROOT / 'build')))
    for pattern, replacement in (*_VARYING, *_INSTALL):
        text = pattern.sub(replacement, text)
    out: list[str] = []
    run: list[tuple[str, int, int | str, str]] = []
    for index, line in enumerate([*text.splitlines(), None]):
        process = _PROCESS_LINE.match(line) if line is not None else None
        if process:
            about, printed = process.groups()
            run.append((about or printed, 0 if about else 1, index, line))
            continue
        if line is not None and _HANDLER_LINE.match(line):
            run.append(('\uffff', 0, line, line))  # after every process, by text
            continue
        out += [item[-1] for item in sorted(run, key=lambda item: item[:3])]
        run = []
        if line is not None:
            out.append(line)
    return out


def cell_text(cell: nbformat.NotebookNode) -> str:
    """What a reader sees of a code cell's outputs, as text."""
    parts = []
    for output in cell.get('outputs', []):
        if output.output_type == 'stream':
            parts.append(output.text)
        elif output.output_type in ('execute_result', 'display_data'):
            parts.append(output.get('data', {}).get('text/plain', ''))
        elif output.output_type == 'error':
            parts.append(f'{output.ename}: {output.evalue}')
    return '\n'.join(part.rstrip('\n') for part in parts)


# -- comparing -------------------------------------------------------------------
@dataclass
class CellDifference:
    cell: int
    source: str
    diff: list[str]
    allowed: str | None = None


@dataclass
class LessonParity:
    lesson: str
    source: str
    cells: int = 0
    errors: dict[str, str] = field(default_factory=dict)  # stack -> why it did not execute
    differences: list[CellDifference] = field(default_factory=list)

    @property
    def differing(self) -> list[CellDifference]:
        return [d for d in self.differences if d.allowed is None]

    @property
    def held(self) -> bool:
        return not self.errors and not self.differing


def load_allowed(path: Path = ALLOWED) -> list[dict]:
    entries = yaml.safe_load(path.read_text()) if path.exists() else None
    for entry in entries or []:
        if not {'lesson', 'cell_contains', 'reason'} <= set(entry):
            raise ValueError(f'{paths.rel(path)}: every entry needs lesson, cell_contains and '
                             f'reason: {entry}')
    return entries or []


def compare(lesson_id: str, source: str, cleanroom: nbformat.NotebookNode,
            jazzy: nbformat.NotebookNode, allowed: Sequence[dict] = ()) -> LessonParity:
    """Cell by cell: the normalised outputs of the same code cell on both stacks."""
    result = LessonParity(lesson_id, source)
    ours = [c for c in cleanroom.cells if c.cell_type == 'code']
    theirs = [c for c in jazzy.cells if c.cell_type == 'code']
    result.cells = len(ours)
    for index, (a, b) in enumerate(zip(ours, theirs, strict=True)):
        entries = allowances(lesson_id, a.source, allowed)
        left, right = compared_lines(a, entries), compared_lines(b, entries)
        if left == right:
            continue
        diff = list(difflib.unified_diff(left, right, 'clean room', 'Jazzy', lineterm='', n=1))
        reason = next((entry['reason'] for entry in entries if 'lines' not in entry), None)
        result.differences.append(CellDifference(index, a.source, diff, reason))
    return result


def allowances(lesson_id: str, source: str, allowed: Sequence[dict]) -> list[dict]:
    """The allow-list entries that apply to the code cell `source` of `lesson_id`."""
    return [entry for entry in allowed
            if entry['lesson'] in (lesson_id, '*') and entry['cell_contains'] in source]


def compared_lines(cell: nbformat.NotebookNode, entries: Sequence[dict]) -> list[str]:
    """A code cell's outputs as parity compares them: normalised, without the lines
    an allow-list entry lets differ (`entries`, from :func:`allowances`)."""
    lines = normalise(cell_text(cell), [JAZZY_BUILD])
    for entry in entries:
        if 'lines' in entry:  # only these lines may differ; the rest is compared
            lines = [line for line in lines if not re.search(entry['lines'], line)]
    return lines
