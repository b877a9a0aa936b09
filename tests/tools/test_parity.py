"""The parity command's comparison: what it normalises, what it reports."""
from __future__ import annotations

import nbformat
from textbook import parity, paths
from textbook.parity import table
from textbook.parity_compare import LessonParity, compare, normalise


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
        '[INFO] [a-1]: process has finished cleanly [pid PID]',
        '[INFO] [b-2]: process started with pid [PID]',
        "Action('<launch.actions.group_action.GroupAction object at 0x…>')",
        '--params-file /tmp/launch_params_…',
        'ROS_DOMAIN_ID=… and robot_count 2',
        'Finished <<< my_robot_pkg […s] / […s]',
        '[…s] WARNING:colcon.colcon_core.shell:The following packages',
    ]


def test_the_lines_of_two_processes_may_interleave_each_keeps_its_order():
    ours = ('$ ros2 launch pkg pair.launch.py\n'
            '[INFO] [sensor-1]: process started with pid [11]\n'
            '[sensor-1] [INFO] [1795793058.1] [sensor]: Reading #1\n'
            '[INFO] [processor-2]: process started with pid [12]\n'
            '[processor-2] [INFO] [1795793058.2] [processor]: Received #1\n'
            '[sensor-1] [INFO] [1795793058.3] [sensor]: Reading #2\n'
            '[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)\n'
            '[INFO] [processor-2]: process has finished cleanly [pid 12]\n'
            '[INFO] [sensor-1]: process has finished cleanly [pid 11]\n')
    theirs = ('$ ros2 launch pkg pair.launch.py\n'
              '[INFO] [processor-2]: process started with pid [22]\n'
              '[INFO] [sensor-1]: process started with pid [21]\n'
              '[processor-2] [INFO] [1795793158.2] [processor]: Received #1\n'
              '[sensor-1] [INFO] [1795793158.1] [sensor]: Reading #1\n'
              '[sensor-1] [INFO] [1795793158.3] [sensor]: Reading #2\n'
              '[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)\n'
              '[INFO] [sensor-1]: process has finished cleanly [pid 21]\n'
              '[INFO] [processor-2]: process has finished cleanly [pid 22]\n')
    assert normalise(ours) == normalise(theirs)
    # ... but not a process's own lines in another order, nor across launch's own lines
    swapped = theirs.replace('Reading #1', 'Reading #X').replace('Reading #2', 'Reading #1')
    assert normalise(ours) != normalise(swapped.replace('Reading #X', 'Reading #2'))
    late = ours.replace('[sensor-1] [INFO] [1795793058.3] [sensor]: Reading #2\n', '').replace(
        '(SIGINT)\n', '(SIGINT)\n[sensor-1] [INFO] [1795793058.3] [sensor]: Reading #2\n')
    assert normalise(ours) != normalise(late)


def test_handlers_and_a_process_s_exit_may_come_before_its_output():
    ours = ('[INFO] [greeter-2]: process started with pid [1]\n'
            '[greeter-2] robot alpha works in /tmp\n'
            '[INFO] [greeter-2]: process has finished cleanly [pid 1]\n'
            '[INFO] [launch.user]: greeter said: robot alpha works in /tmp\n'
            '[INFO] [launch.user]: system_info-1 exited with code 0\n')
    theirs = ('[INFO] [greeter-2]: process started with pid [2]\n'
              '[INFO] [launch.user]: system_info-1 exited with code 0\n'
              '[INFO] [greeter-2]: process has finished cleanly [pid 2]\n'
              '[INFO] [launch.user]: greeter said: robot alpha works in /tmp\n'
              '[greeter-2] robot alpha works in /tmp\n')
    assert normalise(ours) == normalise(theirs)
    assert normalise(ours) != normalise(theirs.replace('exited with code 0', 'exited with code 1'))


def test_launch_log_times_and_node_log_files_vary():
    assert normalise('1795794232.2234139 [INFO] [b-2]: process started with pid [7]\n'
                     '1795794232.3276281 [INFO] [a-1]: process started with pid [8]\n'
                     '/root/.ros/log/python3.11_20022_1795794222494.log\n'
                     'a-1 has the process ID 20445\n'
                     'params_file:=/tmp/ex64_qe1ov5gk/other_robot.yaml /tmp/tmpab_d3f9z') == [
        '[INFO] [a-1]: process started with pid [PID]',
        '[INFO] [b-2]: process started with pid [PID]',
        '/root/.ros/log/python3_PID_TIME.log',
        'a-1 has the process ID PID',
        'params_file:=/tmp/ex64_…/other_robot.yaml /tmp/tmp…']


def test_how_long_tests_took_is_not_a_difference():
    assert normalise('Ran 3 tests in 1.198s\nRan 1 test in 15.4s\nRan out in 2.5s') == [
        'Ran 3 tests in …s', 'Ran 1 test in …s', 'Ran out in 2.5s']
    assert normalise('1 passed, 2 deselected, 2 warnings in 2.51s\n'
                     '===== 3 failed, 2 passed in 72.30s (0:01:12) =====') == [
        '1 passed, 2 deselected, 2 warnings in …s', '===== 3 failed, 2 passed in …s =====']


def test_where_an_install_keeps_python_is_not_a_difference():
    venv = ('/work/main/.venv/bin/python /work/main/build/ws/install/pkg/lib/pkg/node '
            '--ros-args\n  File "/work/main/.venv/lib/python3.11/site-packages/rclpy/node.py", '
            'line 388, in declare_parameter')
    ubuntu = ('/usr/bin/python3 /work/main/build/ws/install/pkg/lib/pkg/node --ros-args\n'
              '  File "/opt/ros/jazzy/lib/python3.12/site-packages/rclpy/node.py", '
              'line 388, in declare_parameter')
    assert normalise(venv) == normalise(ubuntu) == [
        'python3 /work/main/build/ws/install/pkg/lib/pkg/node --ros-args',
        '  File "site-packages/rclpy/node.py", line 388, in declare_parameter']
    shown = '~/ros2-launch-textbook/.venv/bin/python ~/ros2-launch-textbook/build/ws/x'
    assert normalise(shown) == ['python3 ~/ros2-launch-textbook/build/ws/x']
    assert normalise('running but not in the spec: /launch_ros_11575') == [
        'running but not in the spec: /launch_ros_PID']
    assert normalise('[WARN] [_ros2cli_20479]: GID: 01.0f.78.fd.d5') == [
        '[WARN] [_ros2cli_PID]: GID: …']


def test_the_second_stacks_build_folder_stands_for_the_first():
    jazzy = paths.ROOT / 'build' / 'jazzy'
    assert normalise(f'{jazzy}/ws/install/x', [jazzy]) == [f"{paths.ROOT / 'build'}/ws/install/x"]
    # as the pages show it (paths.shown)
    assert normalise(paths.shown(f'{jazzy}/ws/install/x'), [jazzy]) == [
        '~/ros2-launch-textbook/build/ws/install/x']


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


def test_an_allowed_line_is_dropped_and_the_rest_of_the_cell_still_compared():
    allowed = [{'lesson': '*', 'cell_contains': 'print', 'lines': '^UserWarning',
                'reason': 'the build machine has no network'}]
    ours = _notebook('OK\n', 'OK\n')
    theirs = _notebook('OK\nUserWarning: offline\n', 'ERROR\nUserWarning: offline\n')
    parity = compare('ch06-99-x', 'x.md', ours, theirs, allowed)
    assert [d.cell for d in parity.differences] == [1]
    assert parity.differing and parity.differences[0].allowed is None


def test_the_table_says_which_stack_a_lesson_did_not_run_on():
    failed = LessonParity('ch06-setup-check', 'lessons/a.md', errors={'Jazzy': 'cell 3 failed'})
    held = compare('ch06-anatomy', 'lessons/b.md', _notebook('a\n'), _notebook('a\n'))
    rows = table([failed, held]).splitlines()
    assert rows[1].endswith('✗ did not run on Jazzy')
    assert rows[2].endswith('✓ held')


def test_the_jazzy_side_starts_from_a_shell_without_the_book():
    book = {'PATH': f'{paths.ROOT}/.venv/bin:/usr/local/bin:/usr/bin', 'VIRTUAL_ENV': 'x',
            'PYTHONPATH': f'{paths.ROOT}/tools', 'AMENT_PREFIX_PATH': 'y',
            'COLCON_PREFIX_PATH': 'z', 'HOME': '/root', 'TEXTBOOK_FRESH': '1'}
    assert parity.without_the_book(book) == {
        'PATH': '/usr/local/bin:/usr/bin', 'HOME': '/root', 'TEXTBOOK_FRESH': '1'}
