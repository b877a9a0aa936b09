"""`python -m textbook parity`: every lesson on both stacks, compared cell by cell.

The book promises that each output on a page is what a student sees on a real
ROS 2 Jazzy.  The site is built on the headless stack (the clean room); this
command executes the lessons a second time with a real Jazzy sourced (by
default the run-only reference in ../shared/jazzy-reference, installed into
build/jazzy-reference) in an environment of its own (build/jazzy/venv, its
products in build/jazzy), and compares the code cells' outputs after
normalising only what varies from run to run (see `normalise`).

Both sides use the lesson cache, so a lesson whose code cells, snippets and
tools did not change is not executed again.  The report goes to
build/parity/report.json and a table to stdout; the exit code is 1 when a
lesson failed on either stack or a cell differs outside the allow-list
(tools/textbook/parity_allowed.yaml, each entry with its reason).
"""
from __future__ import annotations

import argparse
import difflib
import json
import os
import re
import subprocess
import sys
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path

import nbformat
import yaml

from . import paths

JAZZY_BUILD = paths.ROOT / 'build' / 'jazzy'
JAZZY_VENV = JAZZY_BUILD / 'venv'
REFERENCE_INSTALLER = paths.ROOT.parent / 'shared' / 'jazzy-reference' / 'install.sh'
REFERENCE_PREFIX = paths.ROOT / 'build' / 'jazzy-reference'
REPORT = paths.ROOT / 'build' / 'parity' / 'report.json'
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
    builds = [JAZZY_BUILD]
    for index, (a, b) in enumerate(zip(ours, theirs, strict=True)):
        left, right = normalise(cell_text(a), builds), normalise(cell_text(b), builds)
        entries = [entry for entry in allowed
                   if entry['lesson'] in (lesson_id, '*') and entry['cell_contains'] in a.source]
        for entry in entries:
            if 'lines' in entry:  # only these lines may differ; the rest is compared
                left, right = _without(left, entry['lines']), _without(right, entry['lines'])
        if left == right:
            continue
        diff = list(difflib.unified_diff(left, right, 'clean room', 'Jazzy', lineterm='', n=1))
        reason = next((entry['reason'] for entry in entries if 'lines' not in entry), None)
        result.differences.append(CellDifference(index, a.source, diff, reason))
    return result


def _without(lines: list[str], pattern: str) -> list[str]:
    return [line for line in lines if not re.search(pattern, line)]


# -- executing -------------------------------------------------------------------
def execute_here(sources: Sequence[str]) -> dict[str, dict]:
    """Execute (or fetch from the cache) each lesson with this environment's stack;
    source -> {'notebook': path} or {'error': text}.  Runs in the stack's venv."""
    from .execute import LessonExecutionError, publish
    from .lessons import load

    results: dict[str, dict] = {}
    for source in sources:
        try:
            results[source] = {'notebook': str(publish(load(paths.ROOT / source)))}
        except LessonExecutionError as error:
            results[source] = {'error': str(error)}
    return results


def reference_setup(explicit: str | None) -> Path:
    """The setup.bash of the real Jazzy: given, or the shared reference installed."""
    if explicit:
        return Path(explicit).resolve()
    if not REFERENCE_INSTALLER.exists():
        raise SystemExit('parity: no real ROS 2 Jazzy: pass --jazzy /opt/ros/jazzy/setup.bash '
                         f'(or put the reference at {REFERENCE_INSTALLER.parent})')
    done = subprocess.run(['bash', str(REFERENCE_INSTALLER), str(REFERENCE_PREFIX)],
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise SystemExit(f'parity: installing the Jazzy reference failed:\n{done.stderr}')
    return Path(done.stdout.strip().splitlines()[-1])


def without_the_book(environ: Mapping[str, str]) -> dict[str, str]:
    """``environ`` as a shell that never met this checkout has it: no virtual
    environment, no Python, ament or colcon settings, nothing of the checkout on
    PATH (its .venv/bin), so that what is sourced next is all there is."""
    env = {name: value for name, value in environ.items()
           if not name.startswith(('PYTHON', 'AMENT', 'COLCON', 'VIRTUAL_ENV'))}
    env['PATH'] = os.pathsep.join(entry for entry in env.get('PATH', os.defpath).split(os.pathsep)
                                  if not Path(entry).is_relative_to(paths.ROOT))
    return env


def jazzy_environment(setup: Path) -> dict[str, str]:
    """os.environ as after `source SETUP` in a shell :func:`without_the_book`, with
    the build products in build/jazzy, and build/jazzy/venv made (or refreshed) by
    tools/setup_env.sh."""
    clean = without_the_book(os.environ)
    script = f'source {str(setup)!r} >/dev/null && env -0'
    dumped = subprocess.run(['bash', '-c', script], env=clean, capture_output=True,
                            check=True).stdout.decode()
    env = dict(item.split('=', 1) for item in dumped.split('\0') if '=' in item)
    env.update(TEXTBOOK_BUILD=str(JAZZY_BUILD), TEXTBOOK_VENV=str(JAZZY_VENV))
    subprocess.run(['bash', str(paths.TOOLS / 'setup_env.sh')], env=env, check=True)
    return env


def _run_side(python: str, env: dict[str, str] | None, sources: Sequence[str]
              ) -> subprocess.Popen:
    return subprocess.Popen([python, '-m', 'textbook.parity', '--execute-here', *sources],
                            cwd=paths.ROOT, env=env, stdout=subprocess.PIPE, text=True)


def _collect(process: subprocess.Popen, stack: str) -> dict[str, dict]:
    out, _ = process.communicate()
    if process.returncode != 0:
        raise SystemExit(f'parity: executing the lessons on {stack} failed '
                         f'(exit {process.returncode})')
    return json.loads(out.strip().splitlines()[-1])


# -- the command -------------------------------------------------------------------
def run(lesson_paths: Sequence[str], jazzy_setup: str | None) -> list[LessonParity]:
    from .lessons import load_all

    lessons = load_all()
    if lesson_paths:
        wanted = {Path(p).resolve() for p in lesson_paths}
        lessons = [lesson for lesson in lessons if lesson.path.resolve() in wanted]
    sources = [lesson.source for lesson in lessons]
    env = jazzy_environment(reference_setup(jazzy_setup))
    # Both stacks at once, one lesson each: the two cores the build's `jobs` uses.
    jazzy = _run_side(str(JAZZY_VENV / 'bin' / 'python'), env, sources)
    ours = _run_side(sys.executable, None, sources)
    results = {'clean room': _collect(ours, 'the clean room'), 'Jazzy': _collect(jazzy, 'Jazzy')}
    allowed = load_allowed()
    report = []
    for lesson in lessons:
        sides = {stack: results[stack][lesson.source] for stack in results}
        errors = {stack: side['error'] for stack, side in sides.items() if 'error' in side}
        if errors:
            parity = LessonParity(lesson.meta['id'], lesson.source, errors=errors)
        else:
            notebooks = [nbformat.read(sides[stack]['notebook'], as_version=4)
                         for stack in ('clean room', 'Jazzy')]
            parity = compare(lesson.meta['id'], lesson.source, *notebooks, allowed=allowed)
        report.append(parity)
    return report


def table(report: Sequence[LessonParity]) -> str:
    rows = [f'{"lesson":<34} {"cells":>5} {"differ":>6} {"allowed":>7}  parity']
    for parity in report:
        if parity.errors:
            verdict = '✗ did not run on ' + ' and '.join(parity.errors)
        else:
            verdict = '✓ held' if parity.held else '✗ differs'
        allowed = len(parity.differences) - len(parity.differing)
        rows.append(f'{parity.lesson:<34} {parity.cells:>5} {len(parity.differing):>6} '
                    f'{allowed:>7}  {verdict}')
    return '\n'.join(rows)


def details(report: Sequence[LessonParity], most: int = 40) -> str:
    lines = []
    for parity in report:
        for stack, error in parity.errors.items():
            lines += [f'--- {parity.source}: did not run on {stack}', error]
        for difference in parity.differing:
            first = difference.source.strip().splitlines()[0] if difference.source.strip() else ''
            lines += [f'--- {parity.source}, code cell {difference.cell + 1}: {first}',
                      *difference.diff[:most]]
    return '\n'.join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog='python -m textbook parity', description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('lessons', nargs='*', help='lesson files (default: every lesson)')
    parser.add_argument('--jazzy', metavar='SETUP_BASH',
                        help='setup.bash of a real ROS 2 Jazzy (default: the shared reference)')
    parser.add_argument('--execute-here', action='store_true', help=argparse.SUPPRESS)
    options = parser.parse_args(argv)
    if options.execute_here:
        print(json.dumps(execute_here(options.lessons)))
        return 0
    report = run(options.lessons, options.jazzy)
    REPORT.parent.mkdir(parents=True, exist_ok=True)
    REPORT.write_text(json.dumps([{**asdict(p), 'held': p.held} for p in report], indent=1))
    print(details(report))
    print(table(report))
    return 0 if all(parity.held for parity in report) else 1


if __name__ == '__main__':
    sys.exit(main())
