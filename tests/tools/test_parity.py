"""The parity command's comparison: what it normalises, what it reports."""
from __future__ import annotations

import nbformat
from textbook import paths
from textbook.parity import LessonParity, compare, normalise, table


def _notebook(*outputs: str) -> nbformat.NotebookNode:
    notebook = nbformat.v4.new_notebook()
    for text in outputs:
        cell = nbformat.v4.new_code_cell(source=f'print({text[:10]!r})')
        cell.outputs = [nbformat.v4.new_output('stream', name='stdout', text=text)]
        notebook.cells.append(cell)
    notebook.cells.append(nbformat.v4.new_markdown_cell('prose is not compared'))
    return notebook


def test_only_what_varies_between_runs_is_normalised():
    text = ('[INFO] [launch]: All log files can be found below '
            '/root/.ros/log/2026-11-27-08-04-24-791698-vm-24846\n'
            '[INFO] [b-2]: process started with pid [4711]\n'
            '[INFO] [a-1]: process started with pid [4712]\n'
            '[INFO] [a-1]: process has finished cleanly [pid 4712]\n'
            "Action('<launch.actions.group_action.GroupAction object at 0x7f3a9c0b1d90>')\n"
            '--params-file /tmp/launch_params_k2j3h4l5\n'
            'ROS_DOMAIN_ID=42 and robot_count 2\n'
            'Finished <<< my_robot_pkg [3.04s] / [2min 55s]\n'
            '[0.797s] WARNING:colcon.colcon_core.shell:The following packages\n')
    assert normalise(text) == [
        '[INFO] [launch]: All log files can be found below /root/.ros/log/LOG-DIR',
        '[INFO] [a-1]: process started with pid [PID]',
        '[INFO] [b-2]: process started with pid [PID]',
        '[INFO] [a-1]: process has finished cleanly [pid PID]',
        "Action('<launch.actions.group_action.GroupAction object at 0x…>')",
        '--params-file /tmp/launch_params_…',
        'ROS_DOMAIN_ID=… and robot_count 2',
        'Finished <<< my_robot_pkg […s] / […s]',
        '[…s] WARNING:colcon.colcon_core.shell:The following packages',
    ]


def test_the_second_stacks_build_folder_stands_for_the_first():
    jazzy = paths.ROOT / 'build' / 'jazzy'
    assert normalise(f'{jazzy}/ws/install/x', [jazzy]) == [f"{paths.ROOT / 'build'}/ws/install/x"]


def test_identical_cells_hold_and_a_different_one_is_reported_with_its_diff():
    ours = _notebook('same\n', 'exit code 0\n')
    theirs = _notebook('same\n', 'exit code 1\n')
    parity = compare('ch07-bringup', 'lessons/x.md', ours, theirs)
    assert parity.cells == 2 and not parity.held
    [difference] = parity.differing
    assert difference.cell == 1
    assert difference.diff[-2:] == ['-exit code 0', '+exit code 1']


def test_an_allowed_difference_is_kept_apart_with_its_reason():
    allowed = [{'lesson': 'ch07-bringup', 'cell_contains': "'exit code", 'reason': 'why'}]
    parity = compare('ch07-bringup', 'lessons/x.md', _notebook('exit code 0\n'),
                     _notebook('exit code 1\n'), allowed)
    assert parity.held and parity.differing == []
    assert [d.allowed for d in parity.differences] == ['why']


def test_the_table_says_which_stack_a_lesson_did_not_run_on():
    failed = LessonParity('ch06-setup-check', 'lessons/a.md', errors={'Jazzy': 'cell 3 failed'})
    held = compare('ch06-anatomy', 'lessons/b.md', _notebook('a\n'), _notebook('a\n'))
    rows = table([failed, held]).splitlines()
    assert rows[1].endswith('✗ did not run on Jazzy')
    assert rows[2].endswith('✓ held')
