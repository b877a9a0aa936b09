"""The instructor's path: `make lab`, the book's kernel, labkit outside the
repository, and the devcontainer (README: "Teaching from the notebooks").

The kernel is started the way JupyterLab starts it (jupyter_client, by its
kernel spec name), so what a cell sees here is what an instructor's cell sees.
"""
from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import textwrap
import urllib.error
import urllib.request
from pathlib import Path

import labkit
import psutil
import pytest
from jupyter_client.kernelspec import KernelSpecManager
from jupyter_client.manager import start_new_kernel
from labkit import workspace
from textbook import lab, lab_kernel, paths, reaper

from .._polling import wait_for

pytestmark = pytest.mark.lesson  # starts kernels and JupyterLab

# What a lesson's first cell would show, as JSON on one line.
PROBE_CELL = textwrap.dedent("""
    import json, os, labkit
    print(json.dumps({
        'ROS_DOMAIN_ID': os.environ.get('ROS_DOMAIN_ID'),
        'ROS_AUTOMATIC_DISCOVERY_RANGE': os.environ.get('ROS_AUTOMATIC_DISCOVERY_RANGE'),
        'AMENT_PREFIX_PATH': os.environ.get('AMENT_PREFIX_PATH', ''),
        'TEXTBOOK_ROS_LEASE': os.environ.get('TEXTBOOK_ROS_LEASE'),
        'cwd': os.getcwd(),
        'src': sorted(os.listdir('src')),
        'labkit': labkit.__file__,
        'ready': labkit.require_workspace(),
        'workspace': labkit.workspace.book_package_prefix(),
        'pid': os.getpid(),
    }))
""")



def _run_cell(kc, code: str, timeout: float = 120) -> tuple[str, dict]:
    """Execute ``code``; returns its stdout and the reply content."""
    out: list[str] = []

    def hook(message: dict) -> None:
        if message['msg_type'] == 'stream':
            out.append(message['content']['text'])
        elif message['msg_type'] == 'error':
            out.append('\n'.join(message['content']['traceback']))

    reply = kc.execute_interactive(code, output_hook=hook, timeout=timeout)
    return ''.join(out), reply['content']


def _reply_to(kc, msg_id: str) -> dict | None:
    """The next shell reply if it answers ``msg_id`` (None for another one)."""
    reply = kc.get_shell_msg(timeout=60)
    return reply if reply['parent_header'].get('msg_id') == msg_id else None


def test_setup_installed_the_book_kernel_spec_naming_the_launcher():
    spec = KernelSpecManager().get_kernel_spec(lab_kernel.KERNEL_NAME)
    assert Path(spec.resource_dir).is_relative_to(Path(sys.prefix)), spec.resource_dir
    assert spec.display_name == 'ROS 2 launch textbook (Jazzy)'
    assert spec.argv[:3] == [sys.executable, '-m', 'textbook.lab_kernel']
    assert spec.argv[3:] == ['-f', '{connection_file}']
    assert spec.interrupt_mode == 'message'
    assert spec.language == 'python'


def test_book_kernel_runs_a_cell_in_the_book_environment_and_leaves_nothing(ws_install):
    km, kc = start_new_kernel(kernel_name=lab_kernel.KERNEL_NAME, startup_timeout=240)
    launcher = km.provisioner.process.pid
    try:
        text, reply = _run_cell(kc, PROBE_CELL)
        assert reply['status'] == 'ok', text
        seen = json.loads(text.strip().splitlines()[-1])

        # A private domain of its own, not the one of this test process.
        assert int(seen['ROS_DOMAIN_ID']) in range(1, 90)
        assert seen['ROS_DOMAIN_ID'] != os.environ['ROS_DOMAIN_ID']
        assert seen['ROS_AUTOMATIC_DISCOVERY_RANGE'] == 'LOCALHOST'
        assert seen['TEXTBOOK_ROS_LEASE'] not in (None, os.environ.get('TEXTBOOK_ROS_LEASE'))
        # The working folder is a student workspace, as in the book's build: its own
        # install/ (a copy of the book's build) sourced, labkit importable and satisfied.
        workdir = Path(seen['cwd'])
        assert workdir.parent == paths.RUNS
        book_package = str(workdir / 'install' / 'my_robot_pkg')
        assert book_package in seen['AMENT_PREFIX_PATH'].split(os.pathsep)
        assert seen['ready'] is None
        assert seen['workspace'] == book_package
        assert Path(seen['labkit']).resolve() == Path(labkit.__file__).resolve()
        assert 'my_robot_pkg' in seen['src']
        assert (workdir / 'src' / 'my_robot_pkg' / 'package.xml').is_file()

        # An interrupt reaches the cell through the launcher; the kernel stays.
        sleeping = kc.execute("import time; print('sleeping', flush=True); time.sleep(600)")
        wait_for(lambda: 'sleeping' in kc.get_iopub_msg(timeout=60)['content'].get('text', ''),
                  120, 'the sleeping cell to start')
        km.interrupt_kernel()
        interrupted = wait_for(lambda: _reply_to(kc, sleeping), 120, 'the interrupted reply')
        assert interrupted['content'].get('ename') == 'KeyboardInterrupt', interrupted['content']
        text, reply = _run_cell(kc, "print('still here')")
        if reply['status'] == 'aborted':  # arrived while ipykernel still aborted the queue
            text, reply = _run_cell(kc, "print('still here')")  # of the interrupted cell
        assert reply['status'] == 'ok' and 'still here' in text, (reply, text)
    finally:
        kc.stop_channels()
        km.shutdown_kernel()

    assert not psutil.pid_exists(launcher) or \
        psutil.Process(launcher).status() == psutil.STATUS_ZOMBIE
    assert not psutil.pid_exists(seen['pid'])
    assert reaper.find_processes([seen['TEXTBOOK_ROS_LEASE']]) == []
    assert not workdir.exists(), "the lab kernel's working folder was not removed"


def test_require_workspace_passes_with_the_book_workspace_sourced(ros_env, monkeypatch):
    for name, value in ros_env.items():
        monkeypatch.setenv(name, value)
    assert labkit.require_workspace() is None
    assert workspace.missing_requirements() == []
    assert workspace.book_package_prefix() == str(paths.WORKSPACE / 'install' / 'my_robot_pkg')


def test_require_workspace_says_what_to_do_without_ros_or_workspace(monkeypatch, tmp_path):
    monkeypatch.setenv('PATH', str(tmp_path))  # no ros2 here
    monkeypatch.delenv('AMENT_PREFIX_PATH', raising=False)
    with pytest.raises(labkit.WorkspaceNotReadyError) as error:
        labkit.require_workspace()
    message = str(error.value)
    assert '`ros2` command is not on PATH' in message
    assert '`my_robot_pkg` is not on AMENT_PREFIX_PATH' in message
    for step in ('git clone', 'colcon build', 'source install/setup.bash', 'jupyter lab',
                 'source /opt/ros/jazzy/setup.bash'):
        assert step in message


def test_require_workspace_names_only_what_is_missing(ros_env, monkeypatch):
    for name, value in ros_env.items():
        monkeypatch.setenv(name, value)
    prefixes = [p for p in os.environ['AMENT_PREFIX_PATH'].split(os.pathsep)
                if not p.endswith(os.sep + 'my_robot_pkg')]
    monkeypatch.setenv('AMENT_PREFIX_PATH', os.pathsep.join(prefixes))
    missing = workspace.missing_requirements()
    assert len(missing) == 1 and '`my_robot_pkg`' in missing[0], missing


# labkit as `pip install` leaves it: a package folder with no repository around it,
# next to rclhelpers (the README's pip line installs both).
OUTSIDE_SCRIPT = textwrap.dedent("""
    import labkit, labkit.checks, rclhelpers
    print('labkit from', labkit.__file__)
    print('rclhelpers from', rclhelpers.__file__)
    exercise = sorted(labkit.checks.EXERCISES)[0]
    try:
        labkit.exercises.setup(exercise)
    except labkit.WorkspaceNotReadyError as error:
        print('ERROR:', error)
""")


def _labkit_outside(tmp_path: Path) -> tuple[Path, dict[str, str]]:
    site = tmp_path / 'site-packages'
    for package in (paths.TOOLS / 'labkit', paths.TOOLS / 'rclhelpers' / 'src' / 'rclhelpers',
                    paths.TOOLS / 'speccheck' / 'src' / 'speccheck'):  # labkit builds on it
        shutil.copytree(package, site / package.name, ignore=shutil.ignore_patterns('__pycache__'))
    env = {k: v for k, v in os.environ.items() if k != 'LABKIT_SNIPPETS'}
    env['PYTHONPATH'] = str(site)
    return site, env


def test_labkit_outside_the_repository_explains_where_the_exercise_files_come_from(tmp_path):
    site, env = _labkit_outside(tmp_path)
    ws = tmp_path / 'ros2_ws'
    (ws / 'src').mkdir(parents=True)
    result = subprocess.run([sys.executable, '-c', OUTSIDE_SCRIPT], cwd=ws, env=env,
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert f'labkit from {site}' in result.stdout
    assert f'rclhelpers from {site}' in result.stdout
    assert 'ERROR:' in result.stdout
    assert 'LABKIT_SNIPPETS' in result.stdout and 'cp -r' in result.stdout
    assert not (ws / 'src' / 'my_ws_exercises').exists()


def test_labkit_outside_the_repository_uses_the_snippets_copied_into_the_workspace(tmp_path):
    site, env = _labkit_outside(tmp_path)
    ws = tmp_path / 'ros2_ws'
    for folder in ('starters', 'ch06_solutions'):  # what `cp -r snippets/* src/` brings
        shutil.copytree(paths.SNIPPETS / folder, ws / 'src' / folder,
                        ignore=shutil.ignore_patterns('__pycache__'))
    result = subprocess.run([sys.executable, '-c', OUTSIDE_SCRIPT], cwd=ws, env=env,
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert 'ERROR:' not in result.stdout, result.stdout
    assert (ws / 'src' / 'my_ws_exercises' / 'package.xml').is_file()


def test_import_labkit_without_ros_says_what_to_do(tmp_path):
    site, env = _labkit_outside(tmp_path)
    # -S: no site-packages, so no rclpy, as in a Python where ROS 2 is not sourced.
    result = subprocess.run([sys.executable, '-S', '-c', 'import labkit'], cwd=tmp_path, env=env,
                            capture_output=True, text=True, timeout=60)
    assert result.returncode != 0
    assert 'labkit.workspace.WorkspaceNotReadyError' in result.stderr, result.stderr
    assert 'cannot import `rclpy`' in result.stderr
    assert 'source install/setup.bash' in result.stderr


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]


def _get_json(url: str) -> dict | None:
    try:
        with urllib.request.urlopen(url, timeout=5) as response:
            return json.load(response)
    except (urllib.error.URLError, ConnectionError, TimeoutError):
        return None


def test_lab_command_serves_the_lessons_with_only_the_book_kernel():
    port = _free_port()
    env = dict(os.environ, JUPYTER_TOKEN='textbook-test')
    env.pop('BROWSER', None)
    server = subprocess.Popen(
        [sys.executable, '-m', 'textbook', 'lab', '--no-browser', '--address',
         f'127.0.0.1:{port}'], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        text=True)
    base = f'http://127.0.0.1:{port}'
    token = 'token=textbook-test'
    try:
        specs = wait_for(lambda: server.poll() is None and _get_json(
            f'{base}/api/kernelspecs?{token}'), 120, 'JupyterLab to answer')
        assert specs['default'] == lab_kernel.KERNEL_NAME
        assert set(specs['kernelspecs']) == {lab_kernel.KERNEL_NAME}

        # A lesson (MyST markdown) opens as a notebook through jupytext...
        lesson = sorted(paths.LESSONS.rglob('*.md'))[0].relative_to(paths.LESSONS)
        notebook = _get_json(f'{base}/api/contents/{lesson.as_posix()}'
                             f'?type=notebook&content=1&{token}')
        assert notebook is not None and notebook['type'] == 'notebook'
        assert any(cell['cell_type'] == 'code' for cell in notebook['content']['cells'])
        # ...and that is the default viewer of .md files in this lab.
        docmanager = _get_json(
            f'{base}/lab/api/settings/@jupyterlab/docmanager-extension:plugin?{token}')
        viewers = docmanager['schema']['properties']['defaultViewers']['default']
        assert viewers == lab.OVERRIDES['@jupyterlab/docmanager-extension:plugin'][
            'defaultViewers']
    finally:
        server.terminate()
        output = server.communicate(timeout=60)[0]
    assert f'Serving notebooks from local directory: {paths.LESSONS}' in output


def _put_json(url: str, body: dict) -> dict:
    request = urllib.request.Request(url, data=json.dumps(body).encode(), method='PUT',
                                     headers={'Content-Type': 'application/json'})
    with urllib.request.urlopen(request, timeout=30) as response:
        return json.load(response)


def test_saving_a_lesson_from_the_lab_keeps_its_kernelspec(tmp_path):
    source = sorted(paths.LESSONS.rglob('*.md'))[0]
    original = source.read_text()
    assert 'name: python3' in original
    (tmp_path / 'lesson.md').write_text(original)
    port = _free_port()
    env = dict(os.environ, JUPYTER_TOKEN='textbook-test')
    server = subprocess.Popen(
        [sys.executable, '-m', 'jupyterlab',
         *lab.lab_arguments(f'127.0.0.1:{port}', browser=False,
                            folder=lab.write_settings(tmp_path / 'lab'), root=tmp_path)],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    url = f'http://127.0.0.1:{port}/api/contents/lesson.md?token=textbook-test'
    try:
        model = wait_for(lambda: server.poll() is None and _get_json(
            url + '&type=notebook&content=1'), 120, 'JupyterLab to answer')
        notebook = model['content']
        # What JupyterLab records once the book's kernel runs the lesson:
        notebook['metadata']['kernelspec'] = {
            'display_name': lab_kernel.DISPLAY_NAME, 'language': 'python',
            'name': lab_kernel.KERNEL_NAME}
        notebook['cells'][-1]['source'] += '\n# edited in the lab'
        _put_json(url, {'type': 'notebook', 'format': 'json', 'content': notebook})
    finally:
        server.terminate()
        server.communicate(timeout=60)
    saved = (tmp_path / 'lesson.md').read_text()
    assert '# edited in the lab' in saved  # the save happened...
    assert lab_kernel.KERNEL_NAME not in saved  # ...and kept the lesson's kernel
    assert saved.split('\n---', 1)[0] == original.split('\n---', 1)[0]


def test_a_new_text_notebook_saved_from_the_lab_names_the_lessons_kernel(tmp_path):
    book_spec = (f'kernelspec:\n  display_name: {lab_kernel.DISPLAY_NAME}\n  language: python\n'
                 f'  name: {lab_kernel.KERNEL_NAME}\n')
    model = {'type': 'file', 'format': 'text',
             'content': f'---\n{book_spec}---\n\n# A new page\n'}

    class Contents:
        root_dir = str(tmp_path)  # new.md does not exist there yet

    lab.keep_lesson_front_matter(model=model, path='new.md', contents_manager=Contents())
    assert model['content'] == ('---\nkernelspec:\n  display_name: Python 3\n  language: python\n'
                                '  name: python3\n---\n\n# A new page\n')


def test_make_lab_runs_the_lab_command():
    dry_run = subprocess.run(['make', '-n', 'lab'], cwd=paths.ROOT, capture_output=True,
                             text=True, timeout=60)
    assert dry_run.returncode == 0, dry_run.stderr
    assert '-m textbook lab' in dry_run.stdout
    assert 'setup_env.sh' in dry_run.stdout  # the environment is set up first


def test_devcontainer_runs_the_readme_setup_and_forwards_site_and_lab():
    folder = paths.ROOT / '.devcontainer'
    config = json.loads((folder / 'devcontainer.json').read_text())
    assert config['postCreateCommand'] == 'make setup'
    assert {8000, 8888} <= set(config['forwardPorts'])
    dockerfile = (folder / config['build']['dockerfile']).read_text()
    base = next(line.split()[1] for line in dockerfile.splitlines()
                if line.startswith('FROM '))
    assert 'python' in base and '3.11' in base, base
