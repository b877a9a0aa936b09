"""Wrong answers are patches against the solution (labkit.grading.wrong_answers):
each still applies to the current solution and plants a mistake, and one that
no longer applies fails naming its patch file and hunk line."""
from __future__ import annotations

from pathlib import Path

import pytest
from labkit import checks
from labkit.grading import make_wrong_answer, wrong_answers
from labkit.grading.wrong_answers import PatchError

ANSWERS = [pytest.param(exercise, name, id=f'{exercise.id}-{name}')
           for exercise in checks.EXERCISES.values()
           for name in exercise.wrong_answer_patches()]

SOLUTION = 'line 1\nline 2\nline 3\nline 4\n'
PATCH = """# Mistake: line 2 changed
#   over two lines
# Verdict names: line two
--- a/launch/x.launch.py
+++ b/launch/x.launch.py
@@ -1,3 +1,3 @@
 line 1
-line 2
+line two
 line 3
"""


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / 'mistake.patch'
    path.write_text(text)
    return path


@pytest.mark.parametrize(('exercise', 'name'), ANSWERS)
def test_every_wrong_answer_applies_to_the_solution_and_changes_it(exercise, name):
    patch = exercise.wrong_answer_patches()[name]
    assert patch.mistake.startswith('Mistake'), patch.path
    assert patch.verdict_names and all(patch.verdict_names), patch.path
    answer = exercise.wrong_answers()[name]  # raises PatchError if a hunk no longer applies
    assert set(exercise.files) <= set(answer)
    for file in patch.files:
        solution = exercise.solution(file.path)
        before = solution.read_text() if solution.is_file() else None
        assert answer[file.path] != before, f'{patch.path}: {file.path} is the solution'


def test_a_patch_is_read_with_its_header_and_applied(tmp_path):
    patch = wrong_answers.read(_write(tmp_path, PATCH))
    assert patch.mistake == 'Mistake: line 2 changed over two lines'
    assert patch.verdict_names == ('line two',)
    assert patch.apply(lambda relative: SOLUTION) == {
        'launch/x.launch.py': 'line 1\nline two\nline 3\nline 4\n'}


def test_a_patch_whose_context_changed_raises_naming_file_and_line(tmp_path):
    patch = wrong_answers.read(_write(tmp_path, PATCH))
    with pytest.raises(PatchError) as raised:
        patch.apply(lambda relative: SOLUTION.replace('line 3', 'line three'))
    assert str(raised.value).startswith(  # the patch's line ' line 3', in the hunk of line 6
        f'{tmp_path / "mistake.patch"}:10: the hunk of line 6 does not apply to '
        "launch/x.launch.py: line 3 should be 'line 3', the solution has 'line three'")


def test_a_patch_at_a_line_that_moved_does_not_apply(tmp_path):
    patch = wrong_answers.read(_write(tmp_path, PATCH))
    with pytest.raises(PatchError, match=r'mistake\.patch:7: the hunk of line 6 does not apply'):
        patch.apply(lambda relative: 'line 0\n' + SOLUTION)


@pytest.mark.parametrize(('text', 'complaint'), [
    (PATCH.replace('# Verdict names: line two\n', ''), 'needs a "# Mistake: ..." and'),
    (PATCH.replace('# Mistake: line 2 changed\n#   over two lines\n', ''), 'needs a "# Mistake'),
    (PATCH.replace('@@ -1,3 +1,3 @@', '@@ -1,4 +1,3 @@'), 'ends before'),
    (PATCH.replace('+++ b/launch/x.launch.py', '+++ /dev/null'), 'deleting a file'),
    (PATCH.split('--- ')[0], 'no "--- a/<file>"'),
])
def test_a_malformed_patch_is_refused(tmp_path, text, complaint):
    with pytest.raises(PatchError, match='mistake.patch') as raised:
        wrong_answers.read(_write(tmp_path, text))
    assert complaint in str(raised.value)


def test_make_writes_a_patch_of_the_files_that_differ_and_it_applies(tmp_path):
    solutions, edited = tmp_path / 'solutions', tmp_path / 'edited'
    for folder, second in ((solutions, 'line 2\n'), (edited, 'line two\n')):
        (folder / 'launch').mkdir(parents=True)
        (folder / 'launch' / 'x.launch.py').write_text('line 1\n' + second + 'line 3\n')
        (folder / 'launch' / 'same.launch.py').write_text('unchanged\n')
    (edited / 'config').mkdir()
    (edited / 'config' / 'new.yaml').write_text('no final newline')
    patch_file = solutions / 'wrong' / 'ex' / 'mistake.patch'
    assert make_wrong_answer.main([
        str(edited), str(patch_file), '--mistake', 'line 2 changed',
        '--verdict-names', 'line two']) == 0
    patch = wrong_answers.read(patch_file)
    assert patch.verdict_names == ('line two',)
    assert patch.apply(lambda relative: (solutions / relative).read_text()) == {
        'config/new.yaml': 'no final newline', 'launch/x.launch.py': 'line 1\nline two\nline 3\n'}
