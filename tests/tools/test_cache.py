"""The content cache: an unchanged lesson is not executed again; a change to
the lesson, to a snippet it uses, or to the tools executes it again."""
from __future__ import annotations

import shutil

import nbformat
import pytest
from textbook import cache, execute, paths
from textbook.lessons import load

from ._lesson_files import code_cells, write_lesson


@pytest.fixture
def snippets(tmp_path):
    root = tmp_path / 'snippets'
    for name in ('alpha_pkg', 'beta_pkg'):
        (root / name).mkdir(parents=True)
        (root / name / 'node.py').write_text(f'# {name}\n')
    return root


def key_of(path, snippets):
    return cache.lesson_key(load(path), snippets)


def test_key_is_stable_for_unchanged_content(tmp_path, snippets):
    path = write_lesson(tmp_path, code_cells("print('alpha_pkg')"))
    assert key_of(path, snippets) == key_of(path, snippets)


def test_key_changes_with_the_code_cells_not_with_prose(tmp_path, snippets):
    path = write_lesson(tmp_path, code_cells("print('alpha_pkg')"))
    before = key_of(path, snippets)
    path.write_text(path.read_text().replace('# Demo', '# Demo\n\nOne more sentence.'))
    assert key_of(path, snippets) == before, 'a prose edit changed the key'
    path.write_text(path.read_text().replace("print('alpha_pkg')", "print('alpha_pkg', 2)"))
    assert key_of(path, snippets) != before


def test_key_changes_with_cell_tags(tmp_path, snippets):
    path = write_lesson(tmp_path, code_cells('print(1)'))
    before = key_of(path, snippets)
    path.write_text(path.read_text().replace('```{code-cell} ipython3',
                                             '```{code-cell} ipython3\n:tags: [solution]'))
    assert key_of(path, snippets) != before


def test_key_follows_the_packages_a_lesson_uses_and_only_those(tmp_path, snippets):
    path = write_lesson(tmp_path, code_cells('%%bash\nros2 run alpha_pkg node'))
    before = key_of(path, snippets)
    (snippets / 'beta_pkg' / 'node.py').write_text('# changed\n')
    assert key_of(path, snippets) == before, 'an unrelated package invalidated the lesson'
    (snippets / 'alpha_pkg' / 'node.py').write_text('# changed\n')
    assert key_of(path, snippets) != before


def test_a_lesson_that_builds_the_workspace_depends_on_all_snippets(tmp_path, snippets):
    path = write_lesson(tmp_path, code_cells('%%bash\ncolcon build'))
    before = key_of(path, snippets)
    (snippets / 'beta_pkg' / 'node.py').write_text('# changed\n')
    assert key_of(path, snippets) != before


def test_key_changes_with_the_tools(tmp_path, snippets, monkeypatch):
    path = write_lesson(tmp_path, code_cells('print(1)'))
    before = key_of(path, snippets)
    monkeypatch.setattr(cache, '__version__', '99.0')
    assert key_of(path, snippets) != before


def test_key_changes_with_the_ros_stack(tmp_path, snippets, monkeypatch):
    """A sourced ROS 2 (its ros2, colcon, launch on PATH/PYTHONPATH) is another stack."""
    path = write_lesson(tmp_path, code_cells('print(1)'))
    before = key_of(path, snippets)
    ros = tmp_path / 'opt_ros' / 'bin'
    ros.mkdir(parents=True)
    for name in ('ros2', 'colcon'):
        (ros / name).write_text('#!/bin/sh\n')
        (ros / name).chmod(0o755)
    monkeypatch.setattr(paths, 'VENV_BIN', tmp_path / 'no_venv')  # as with no clean room
    monkeypatch.setenv('PATH', str(ros))
    other_stack = key_of(path, snippets)
    assert other_stack != before
    monkeypatch.setenv('AMENT_PREFIX_PATH', str(ros.parent))
    assert key_of(path, snippets) != other_stack


@pytest.fixture
def runs(tmp_path, monkeypatch) -> list[int]:
    """Each execution of a lesson appends to the list; cache and notebooks in tmp_path."""
    monkeypatch.setattr(cache, 'LESSON_CACHE', tmp_path / 'cache')
    monkeypatch.setattr(paths, 'NOTEBOOKS', tmp_path / 'notebooks')
    # the tree may change meanwhile (an editor, a build); only the lesson matters here
    monkeypatch.setattr(cache, 'tools_fingerprint', lambda: 'tools')
    executions: list[int] = []
    real_execute = execute.execute
    monkeypatch.setattr(execute, 'execute',
                        lambda lesson: executions.append(1) or real_execute(lesson))
    return executions


def test_unchanged_lesson_is_not_executed_again(tmp_path, runs):
    path = write_lesson(tmp_path, code_cells('import random\nprint(random.random())'))

    first = execute.publish(load(path))
    output = first.read_text()
    execute.publish(load(path))
    assert len(runs) == 1, 'an unchanged lesson was executed again'
    assert first.read_text() == output

    path.write_text(path.read_text().replace('print(random', "print('changed', random"))
    execute.publish(load(path))
    assert len(runs) == 2, 'a changed lesson was not executed again'
    assert 'changed' in first.read_text()
    shutil.rmtree(tmp_path / 'cache')


def test_a_prose_edit_executes_nothing_and_shows_the_new_prose(tmp_path, runs):
    path = write_lesson(tmp_path, code_cells('import random\nprint(random.random())'))

    first = nbformat.read(execute.publish(load(path)), as_version=4)
    path.write_text(path.read_text().replace('# Demo', '# Demo\n\nA typo fixed.'))
    second = nbformat.read(execute.publish(load(path)), as_version=4)
    assert len(runs) == 1, 'a prose-only edit executed the lesson again'
    assert 'A typo fixed.' in second.cells[0].source
    outputs = [[cell.outputs for cell in nb.cells if cell.cell_type == 'code']
               for nb in (first, second)]
    assert outputs[0] == outputs[1] and outputs[0][0], 'the cached outputs were not kept'
