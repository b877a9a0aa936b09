"""The parity record: a lesson counts as seen on a real Jazzy only while what it
executes and what the clean room prints for it are what they were when parity
held; the site's sentence about a page's outputs says so."""
from __future__ import annotations

import nbformat
from bs4 import BeautifulSoup
from textbook import parity_record, paths
from textbook.header import header_html
from textbook.lessons import load, load_all
from textbook.parity_compare import LessonParity

LESSON = load(paths.LESSONS / 'ch06/L1/05_namespaces_and_remapping.md')
REFERENCE = 'launch 3.4.3, launch_ros 0.26.6, ros2cli 0.32.2, rclpy 7.1.5'


def _notebook(*outputs: str, source: str = 'print()') -> nbformat.NotebookNode:
    notebook = nbformat.v4.new_notebook()
    for text in outputs:
        cell = nbformat.v4.new_code_cell(source)
        cell.outputs = [nbformat.v4.new_output('stream', name='stdout', text=text)]
        notebook.cells.append(cell)
    return notebook


def _held(lesson=LESSON) -> LessonParity:
    return LessonParity(lesson.id, lesson.source, cells=1)


def test_outputs_hash_ignores_what_parity_normalises_and_sees_the_rest():
    first = parity_record.outputs_hash(LESSON, _notebook('process started with pid [12]\n'), [])
    again = parity_record.outputs_hash(LESSON, _notebook('process started with pid [345]\n'), [])
    other = parity_record.outputs_hash(LESSON, _notebook('process has died [pid 12]\n'), [])
    assert first == again != other


def test_outputs_hash_leaves_out_what_the_allow_list_lets_differ():
    lines = [{'lesson': '*', 'cell_contains': 'hz', 'lines': '^average rate', 'reason': 'r'}]
    whole = [{'lesson': LESSON.id, 'cell_contains': 'hz', 'reason': 'r'}]
    a, b = _notebook('ok\naverage rate: 1.9\n', source='hz'), _notebook(
        'ok\naverage rate: 2.1\n', source='hz')
    assert parity_record.outputs_hash(LESSON, a, lines) == \
        parity_record.outputs_hash(LESSON, b, lines)
    c = _notebook('anything at all\n', source='hz')
    assert parity_record.outputs_hash(LESSON, a, whole) == \
        parity_record.outputs_hash(LESSON, c, whole)
    assert parity_record.outputs_hash(LESSON, a, []) != parity_record.outputs_hash(LESSON, b, [])


def test_a_lesson_holds_while_its_outputs_are_those_parity_saw(tmp_path):
    record = tmp_path / 'record.yaml'
    seen = _notebook('Boolean value is: True\n')
    parity_record.update([(LESSON, _held(), seen)], REFERENCE, record)
    loaded = parity_record.load(record)
    assert parity_record.status(LESSON, seen, loaded).held
    assert parity_record.status(LESSON, seen, loaded).reference == REFERENCE
    assert not parity_record.status(LESSON, _notebook('Boolean value is: False\n'), loaded).held
    other = next(lesson for lesson in load_all() if lesson.id != LESSON.id)
    assert not parity_record.status(other, seen, loaded).held  # no entry of its own


def test_a_changed_lesson_is_no_longer_covered(tmp_path):
    record = tmp_path / 'record.yaml'
    seen = _notebook('x\n')
    parity_record.update([(LESSON, _held(), seen)], REFERENCE, record)
    entry = parity_record.load(record)[LESSON.id]
    changed = {LESSON.id: {**entry, 'inputs': 'the hash of an older version'}}
    assert not parity_record.status(LESSON, seen, changed).held


def test_a_lesson_that_differs_or_failed_is_taken_out(tmp_path):
    record = tmp_path / 'record.yaml'
    parity_record.update([(LESSON, _held(), _notebook('x\n'))], REFERENCE, record)
    failed = LessonParity(LESSON.id, LESSON.source, errors={'Jazzy': 'cell 3 failed'})
    parity_record.update([(LESSON, failed, None)], REFERENCE, record)
    assert LESSON.id not in parity_record.load(record)
    assert record.read_text().startswith('# Lessons whose outputs')


def test_the_committed_record_names_only_lessons_that_exist():
    ids = {lesson.id for lesson in load_all()}
    assert set(parity_record.load()) <= ids
    for entry in parity_record.load().values():
        assert set(entry) == {'inputs', 'outputs', 'checked', 'reference'}, entry


def test_the_page_says_what_produced_its_outputs(tmp_path):
    seen = _notebook('x\n')
    record = tmp_path / 'record.yaml'
    parity_record.update([(LESSON, _held(), seen)], REFERENCE, record)
    held = parity_record.provenance(LESSON, seen, parity_record.load(record))
    assert parity_record.on_clean_room()  # the book's tests run on the clean room
    assert held.startswith("executed on the book's headless stack") and REFERENCE in held
    unchecked = parity_record.provenance(LESSON, _notebook('y\n'), parity_record.load(record))
    assert 'not compared with a real ROS 2 Jazzy' in unchecked
    box = BeautifulSoup(header_html(LESSON.meta, [], unchecked), 'html.parser')
    assert box.select_one('.textbook-outputs').get_text().startswith('Outputs on this page:')
