"""Lesson execution: real outputs in an isolated domain, errors that name the
lesson, the cell and the error, hang protection, and no leftover processes."""
from __future__ import annotations

import psutil
import pytest
from labkit import exercises
from textbook import execute, paths, workspace
from textbook.lessons import load

from ._lesson_files import META, code_cells, write_lesson

pytestmark = pytest.mark.lesson  # executes small notebooks in kernels, as the build does


def test_outputs_are_recorded_in_an_isolated_sourced_environment(tmp_path):
    lesson = load(write_lesson(tmp_path, code_cells(
        "import os\n"
        "print(os.environ['ROS_DOMAIN_ID'], os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'])",
        '%%bash\nros2 pkg prefix my_robot_pkg',
        '%%bash\nls -F src/',
        "print(os.environ.get('TEXTBOOK_APPLY_SOLUTIONS'))",
        '%%bash\ncolcon build --packages-select my_robot_pkg 2>&1 | grep -v "^\\[[0-9.]*s\\]"')))
    notebook = execute.execute(lesson)
    outputs = [''.join(o.get('text', '') for o in c.outputs) for c in notebook.cells
               if c.cell_type == 'code']
    domain, discovery = outputs[0].split()
    assert 1 <= int(domain) <= 89 and discovery == 'LOCALHOST'
    # the lesson's own workspace is built and sourced, shown as a student's ~/ros2_ws
    assert outputs[1] == '~/ros2_ws/install/my_robot_pkg\n'
    # src/ holds plain folders (copies) of the book's packages, like a student's workspace
    assert 'my_robot_pkg/' in outputs[2].split()
    assert outputs[3].strip() == '1'  # the book's build applies solutions and fails on a check
    # one package rebuilt: the others are built in this workspace, so colcon does not
    # warn that they "haven't been built" (as in a workspace built once by the student)
    assert 'Finished <<< my_robot_pkg' in outputs[4]
    assert 'WARNING' not in outputs[4], outputs[4]


def test_a_lesson_that_builds_the_workspace_starts_without_install(tmp_path):
    path = write_lesson(tmp_path, code_cells('%%bash\nls'), {**META, 'builds_workspace': True})
    notebook = execute.execute(load(path))
    (cell,) = [c for c in notebook.cells if c.cell_type == 'code']
    assert ''.join(o.get('text', '') for o in cell.outputs) == 'src\n'


def test_a_lesson_editing_src_never_changes_snippets(tmp_path):
    lesson = load(write_lesson(tmp_path, code_cells(
        "%%bash\necho '# edited by a lesson' >> src/my_robot_pkg/setup.py\n"
        "mkdir -p src/my_ws_exercises && touch src/my_ws_exercises/package.xml")))
    before = (paths.SNIPPETS / 'my_robot_pkg' / 'setup.py').read_bytes()
    execute.execute(lesson)
    assert (paths.SNIPPETS / 'my_robot_pkg' / 'setup.py').read_bytes() == before
    assert not (paths.SNIPPETS / 'my_ws_exercises').exists()


def test_a_lesson_sees_no_bytecode_that_earlier_runs_left_in_the_books_install(tmp_path):
    # `ros2 launch` writes __pycache__/ next to a launch file it loads (as Jazzy's does);
    # a lesson's own `ls` must not depend on which tests used the book's build before.
    launch = workspace.ensure_built() / 'my_robot_pkg/share/my_robot_pkg/launch'
    (launch / '__pycache__').mkdir(exist_ok=True)
    lesson = load(write_lesson(tmp_path, code_cells(
        '%%bash\nls -a install/my_robot_pkg/share/my_robot_pkg/launch')))
    notebook = execute.execute(lesson)
    (cell,) = [c for c in notebook.cells if c.cell_type == 'code']
    listed = ''.join(o.get('text', '') for o in cell.outputs).split()
    assert 'robot_system.launch.py' in listed and '__pycache__' not in listed


def test_the_build_flag_is_the_one_labkit_reads():
    assert execute.APPLY_SOLUTIONS == exercises.APPLY_SOLUTIONS


def test_failing_cell_names_lesson_line_cell_and_error(tmp_path):
    path = write_lesson(tmp_path, code_cells('x = 1', "print('before')\n1 / 0"))
    line = path.read_text().splitlines().index("print('before')") + 1
    with pytest.raises(execute.LessonExecutionError) as error:
        execute.execute(load(path))
    message = str(error.value)
    assert f"demo.md:{line}: cell 3 (\"print('before')\") failed" in message
    assert 'ZeroDivisionError: division by zero' in message
    assert '| before' in message  # what the cell printed before failing


def test_failing_shell_command_fails_the_lesson(tmp_path):
    lesson = load(write_lesson(tmp_path, code_cells('%%bash\necho trying\nexit 3')))
    with pytest.raises(execute.LessonExecutionError, match='CalledProcessError'):
        execute.execute(lesson)


def test_a_hung_cell_is_stopped_and_reported(tmp_path):
    lesson = load(write_lesson(tmp_path, code_cells('import time\ntime.sleep(60)')))
    with pytest.raises(execute.LessonExecutionError, match=r'no result after 3 s'):
        execute.execute(lesson, timeout=3)


def test_processes_left_running_are_killed_and_fail_the_lesson(tmp_path):
    # In a session of its own, the process survives the kernel's process group.
    lesson = load(write_lesson(tmp_path, code_cells(
        "import subprocess\n"
        "proc = subprocess.Popen(['sleep', '300'], start_new_session=True)")))
    with pytest.raises(execute.LessonExecutionError, match='still running') as error:
        execute.execute(lesson)
    assert 'sleep 300' in str(error.value)
    pid = int(str(error.value).split('pid ')[1].split(':')[0])
    assert not psutil.pid_exists(pid) or psutil.Process(pid).status() == psutil.STATUS_ZOMBIE


def test_a_lesson_runs_where_no_project_configuration_applies(tmp_path):
    """pytest, run by a lesson's `colcon test`, finds the rootdir and ini a student's
    ~/ros2_ws has: none of this repository's files above the workspace."""
    cell = (
        'import os, subprocess\n'
        "os.makedirs('src/demo/test', exist_ok=True)\n"
        "open('src/demo/test/test_demo.py', 'w').write('def test_demo():\\n    pass\\n')\n"
        "command = ['python', '-m', 'pytest', 'src/demo/test', '-p', 'no:cacheprovider']\n"
        'print(subprocess.run(command, capture_output=True, text=True).stdout)')
    notebook = execute.execute(load(write_lesson(tmp_path, code_cells(cell))))
    output = ''.join(out.get('text', '') for cell in notebook.cells
                     for out in cell.get('outputs', []))
    assert '1 passed' in output, output
    rootdir = next(line for line in output.splitlines() if line.startswith('rootdir: '))
    assert str(paths.ROOT) not in rootdir and 'configfile' not in output, output
