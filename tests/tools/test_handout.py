"""The handout: the executed lesson without its solutions, everything else kept."""
from __future__ import annotations

import nbformat
from textbook.handout import handout_name, without_solutions


def _cell(kind: str, source: str, *tags: str) -> nbformat.NotebookNode:
    cell = (nbformat.v4.new_code_cell if kind == 'code' else nbformat.v4.new_markdown_cell)(
        source)
    cell.metadata['tags'] = list(tags)
    return cell


def test_solution_cells_go_and_everything_else_stays_as_executed():
    notebook = nbformat.v4.new_notebook()
    check = _cell('code', 'labkit.exercises.check("ex65")')
    check.outputs = [nbformat.v4.new_output('stream', name='stdout', text='✓ /ranges\n')]
    notebook.cells = [_cell('markdown', 'Exercise 1'), _cell('markdown', 'A hint', 'hint'),
                      _cell('markdown', 'The answer is absolute', 'solution'),
                      _cell('code', "labkit.exercises.solution('ex65')", 'solution'), check]
    handout = without_solutions(notebook)
    assert [cell.source for cell in handout.cells] == [
        'Exercise 1', 'A hint', 'labkit.exercises.check("ex65")']
    assert handout.cells[-1].outputs == check.outputs
    assert len(notebook.cells) == 5  # the executed notebook itself is untouched


def test_the_handout_is_named_after_the_notebook():
    assert handout_name('05_namespaces_and_remapping.ipynb') == \
        '05_namespaces_and_remapping.no-solutions.ipynb'
