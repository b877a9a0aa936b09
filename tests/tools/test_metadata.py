"""The lesson metadata schema: good metadata loads, anything missing or
malformed fails naming the lesson file and the field."""
from __future__ import annotations

import copy

import pytest
import yaml
from textbook.lessons import LessonError, load, load_all
from textbook.metadata import MetadataError

from ._lesson_files import META

GOOD = META


def write_lesson(root, meta, name='demo.md', chapter='ch06', layer='L1', body=None):
    front = {'kernelspec': {'name': 'python3', 'display_name': 'Python 3',
                            'language': 'python'}}
    if meta is not None:
        front['textbook'] = meta
    path = root / chapter / layer / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text('---\n' + yaml.safe_dump(front) + '---\n\n'
                    + (body or "# Demo\n\n## Key points\n\n"
                                "```{code-cell} ipython3\nprint('hi')\n```\n"))
    return path


def test_good_metadata_loads(tmp_path):
    lesson = load(write_lesson(tmp_path, GOOD))
    assert lesson.id == 'ch06-demo'
    assert lesson.site_path == 'ch06/L1/demo.ipynb'
    assert [c.cell_type for c in lesson.notebook.cells] == ['markdown', 'code']


@pytest.mark.parametrize('field,value,message', [
    ('id', None, "'textbook.id': 'id' is a required property"),
    ('title', '', "'textbook.title'"),
    ('chapter', 5, "'textbook.chapter': 5 is not one of [6, 7]"),
    ('chapter', '6', "'textbook.chapter'"),
    ('layer', 'L5', "'textbook.layer': 'L5' is not one of"),
    ('duration_minutes', 0, "'textbook.duration_minutes'"),
    ('duration_minutes', '20 min', "'textbook.duration_minutes'"),
    ('proficiency', 'B2', "'textbook.proficiency': 'B2' is not one of ['A2', 'B1', 'C2']"),
    ('hardware_tier', 9, "'textbook.hardware_tier'"),
    ('tier_1_path', None, "'textbook.tier_1_path': 'tier_1_path' is a required property"),
    ('learning_objectives', [], "'textbook.learning_objectives'"),
    ('learning_objectives', 'one', "'textbook.learning_objectives'"),
    ('skills', [''], "'textbook.skills.0'"),
    ('prerequisites', 'ch06-a', "'textbook.prerequisites'"),
    ('id', 'Has Spaces', "'textbook.id'"),
])
def test_malformed_field_fails_naming_file_and_field(tmp_path, field, value, message):
    meta = copy.deepcopy(GOOD)
    if value is None:
        del meta[field]
    else:
        meta[field] = value
    path = write_lesson(tmp_path, meta)
    with pytest.raises(MetadataError) as error:
        load(path)
    assert str(path) in str(error.value) or 'demo.md' in str(error.value)
    assert message in str(error.value)


def test_unknown_field_fails(tmp_path):
    with pytest.raises(MetadataError, match='Additional properties are not allowed'):
        load(write_lesson(tmp_path, dict(GOOD, level='easy')))


def test_missing_metadata_block_fails(tmp_path):
    with pytest.raises(MetadataError, match="no 'textbook:' metadata"):
        load(write_lesson(tmp_path, None))


def test_lesson_in_the_wrong_folder_fails(tmp_path):
    path = write_lesson(tmp_path, GOOD, layer='L2')
    with pytest.raises(MetadataError, match='belongs in lessons/ch06/L1/'):
        load(path)


def test_duplicate_ids_and_unknown_prerequisites_fail(tmp_path):
    write_lesson(tmp_path, GOOD, name='a.md')
    write_lesson(tmp_path, dict(GOOD, prerequisites=['ch06-nope']), name='b.md')
    with pytest.raises(MetadataError) as error:
        load_all(tmp_path)
    assert "'ch06-demo' is already used by" in str(error.value)
    assert "'ch06-nope' is not the id of any lesson" in str(error.value)


def test_all_broken_lessons_are_reported_at_once(tmp_path):
    write_lesson(tmp_path, dict(GOOD, layer='L9'), name='a.md')
    b = write_lesson(tmp_path, dict(GOOD, id='b'), name='b.md',
                     body='```{snippet} no/such/file.py\n```\n')
    line = b.read_text().splitlines().index('```{snippet} no/such/file.py') + 1
    with pytest.raises(LessonError) as error:
        load_all(tmp_path)
    assert "a.md: metadata field 'textbook.layer'" in str(error.value)
    assert f'b.md:{line}: snippet file snippets/no/such/file.py does not exist' \
        in str(error.value)


def test_the_books_lessons_pass():
    assert load_all(), 'lessons/ has no lessons'
