"""Every lesson executes through nbclient, as the site build executes it
(one test per lesson).  A lesson whose cache key is unchanged (its text, the
snippets it uses, the tools and the ROS stack) is taken from the cache, as
the site build takes it; ``TEXTBOOK_FRESH=1`` executes every lesson anyway.
Lessons run on any test worker, next to other tests: a lesson spends much of
its time waiting for ROS discovery, and the cache's per-lesson lock keeps a
lesson from being executed twice when the site build wants it too."""
from __future__ import annotations

import re

import nbformat
import pytest
from textbook import execute, paths, settings
from textbook.lessons import discover, load

LESSONS = discover()

COLOUR_CODE = re.compile(r'\x1b\[[0-9;]*m')
#: What a page must never show (the guide: no build-machine paths, no colour
#: codes): each with what it means when it turns up (looked for in the line
#: with its colour codes taken out, except the first).
UNREADABLE = {
    COLOUR_CODE: 'a terminal colour code',
    re.compile(re.escape(str(paths.ROOT))): "the build machine's checkout (paths.shown writes it)",
    re.compile(r'\[RTPS_\w+ Error\]'): (
        "a Fast DDS transport error (this machine's /dev/shm: a live participant's "
        'shared-memory port was removed), not what a student sees'),
}


def unreadable_lines(notebook) -> list[str]:
    """The output lines of ``notebook`` that a page must not show, each with why."""
    found = []
    for index, cell in enumerate(notebook.cells):
        for output in cell.get('outputs', []):
            texts = [output.get('text', ''),
                     *(v for k, v in output.get('data', {}).items() if k.startswith('text/'))]
            for line in ''.join(''.join(t) if isinstance(t, list) else t
                                for t in texts).splitlines():
                plain = COLOUR_CODE.sub('', line)
                found += [f'cell {index}: {why}: {plain[:160]!r}'
                          for pattern, why in UNREADABLE.items()
                          if pattern.search(line if pattern is COLOUR_CODE else plain)]
    return found


def test_there_are_lessons():
    assert LESSONS, 'lessons/ has no lessons'


@pytest.mark.timeout(900)
@pytest.mark.parametrize('path', LESSONS, ids=lambda p: str(p.relative_to(p.parents[2])))
def test_lesson_executes(path):
    lesson = load(path)
    notebook = execute.refresh(lesson) if settings.load().fresh else execute.executed(lesson)
    code_cells = [cell for cell in notebook.cells if cell.cell_type == 'code']
    assert all(cell.get('execution_count') for cell in code_cells), 'a code cell did not run'
    errors = [out for cell in code_cells for out in cell.outputs if out.output_type == 'error']
    assert not errors, errors
    assert not unreadable_lines(notebook), '\n'.join(unreadable_lines(notebook))


def test_unreadable_lines_are_found():
    """The page check above finds each kind of unreadable line (and passes a clean one)."""
    shm = ('\x1b[37;1m2026-11-28 00:26:16.495 \x1b[31;1m[\x1b[37;1mRTPS_TRANSPORT_SHM\x1b[31;1m '
           'Error] \x1b[37mFailed init_port fastrtps_port7000: open_and_lock_file failed')
    cell = nbformat.v4.new_code_cell(outputs=[
        nbformat.v4.new_output('stream', text=f'{shm}\nString value is: rover\n'),
        nbformat.v4.new_output('display_data', data={'text/plain': f'{paths.ROOT}/.venv/bin/ros2'}),
        nbformat.v4.new_output('stream', text='[RTPS_TRANSPORT_SHM Error] Failed init_port\n'),
    ])
    clean = nbformat.v4.new_code_cell(outputs=[nbformat.v4.new_output(
        'stream', text=paths.shown(f'{paths.ROOT}/.venv/bin/ros2\nString value is: rover\n'))])
    found = unreadable_lines(nbformat.v4.new_notebook(cells=[clean, cell]))
    kinds = [why for line in found for why in UNREADABLE.values() if why in line]
    colour, checkout, fast_dds = UNREADABLE.values()
    assert [line.split(':')[0] for line in found] == ['cell 1'] * 4, found
    assert kinds == [colour, fast_dds, checkout, fast_dds], found
