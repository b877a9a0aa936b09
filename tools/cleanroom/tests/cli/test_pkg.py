"""`ros2 pkg list|prefix|executables|xml|create` in Jazzy's words (recorded from the Jazzy
reference)."""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

PREFIX = sys.prefix
ROS2 = str(Path(sys.executable).with_name('ros2'))

STD_SRVS_XML = """\
<package format="3">
  <name>std_srvs</name>
  <version>5.3.6</version>
  <description>A package containing some standard service definitions.</description>

  <maintainer email="tfoote@openrobotics.org">Tully Foote</maintainer>

  <license>Apache License 2.0</license>

  <author email="dthomas@osrfoundation.org">Dirk Thomas</author>
  <author email="geoff@openrobotics.org">Geoffrey Biggs</author>
  <author email="michael@openrobotics.org">Michael Carroll</author>
  <author email="michel@ekumenlabs.com">Michel Hidalgo</author>

  <buildtool_depend>ament_cmake</buildtool_depend>

  <buildtool_depend>rosidl_default_generators</buildtool_depend>

  <exec_depend>rosidl_default_runtime</exec_depend>

  <test_depend>ament_lint_common</test_depend>

  <member_of_group>rosidl_interface_packages</member_of_group>

  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
"""

PREFIX_HELP = """\
usage: ros2 pkg prefix [-h] [--share] package_name

Output the prefix path of a package

positional arguments:
  package_name  The package name

options:
  -h, --help    show this help message and exit
  --share       Show share directory for the package
"""


@pytest.fixture(scope='module')
def pkg(ros2):
    def run(*args):
        return ros2('pkg', *args, env={'AMENT_PREFIX_PATH': PREFIX, 'COLUMNS': '80'})
    return run


def test_list_sorted(pkg):
    result = pkg('list')
    names = result.stdout.splitlines()
    assert result.returncode == 0 and names == sorted(names)
    assert names[:3] == ['action_msgs', 'ament_cmake', 'ament_cmake_core']
    assert 'std_msgs' in names


def test_prefix(pkg):
    assert (pkg('prefix', 'std_msgs').returncode, pkg('prefix', 'std_msgs').stdout) == \
        (0, PREFIX + '\n')
    assert pkg('prefix', '--share', 'std_msgs').stdout == f'{PREFIX}/share/std_msgs\n'
    result = pkg('prefix', 'nosuch')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', 'Package not found\n')
    assert pkg('prefix', '-h').stdout == PREFIX_HELP


def test_executables(pkg):
    assert pkg('executables', 'rosidl_adapter').stdout == (
        'rosidl_adapter action2idl.py\nrosidl_adapter msg2idl.py\nrosidl_adapter srv2idl.py\n')
    assert pkg('executables', '--full-path', 'rosidl_adapter').stdout == ''.join(
        f'{PREFIX}/lib/rosidl_adapter/{name}\n'
        for name in ('action2idl.py', 'msg2idl.py', 'srv2idl.py'))
    result = pkg('executables', 'std_msgs')
    assert (result.returncode, result.stdout) == (0, '')
    result = pkg('executables', 'nosuch')
    assert (result.returncode, result.stdout, result.stderr) == (
        1, '', "Package 'nosuch' not found\n")
    lines = pkg('executables').stdout.splitlines()
    assert lines[:2] == ['rosidl_adapter action2idl.py', 'rosidl_adapter msg2idl.py']
    assert lines == sorted(lines)


def test_xml(pkg):
    result = pkg('xml', 'std_srvs')
    assert (result.returncode, result.stdout) == (0, STD_SRVS_XML)
    assert pkg('xml', '-t', 'version', 'std_srvs').stdout == '5.3.6\n'
    assert pkg('xml', '-t', 'buildtool_depend', 'std_srvs').stdout == \
        'ament_cmake\nrosidl_default_generators\n'
    assert pkg('xml', '-t', 'export', 'std_srvs').stdout == '\n    \n'
    result = pkg('xml', '-t', 'nosuch', 'std_srvs')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', 'XML tag not found\n')
    result = pkg('xml', 'nosuch')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', 'Package not found\n')


def test_xml_drops_comments_as_jazzy(pkg):
    out = pkg('xml', 'rcl_interfaces').stdout
    assert '<ros1_bridge mapping_rules="mapping_rules.yaml" />' in out
    assert '<?xml' not in out


# --- ros2 pkg create -------------------------------------------------------------------------

#: Expected results of `ros2 pkg create` (exit code, stdout with the working directory as
#: <CWD>, stderr, and every folder (None) and file created, a LICENSE as its sha256), recorded
#: from the Jazzy reference by running each case's arguments in an empty working directory.
#: (The reference needed empy 3.3.4, Ubuntu 24.04's python3-empy, first on its PYTHONPATH: with
#: the empy 4 it ships, its `pkg create` stops with "module 'em' has no attribute
#: 'BUFFERED_OPT'" after writing package.xml.)
CREATE_EXPECTED = json.loads(
    (Path(__file__).with_name('pkg_create_expected.json')).read_text(encoding='utf-8'))


def _create(tmp_path: Path, *args: str, env: dict[str, str] | None = None,
            cwd: Path | None = None) -> subprocess.CompletedProcess:
    cwd = cwd or tmp_path
    cwd.mkdir(parents=True, exist_ok=True)
    return subprocess.run([ROS2, 'pkg', 'create', *args], cwd=cwd, capture_output=True,
                          text=True, timeout=30, env={**os.environ, 'COLUMNS': '80', **(env or {})})


def _tree(root: Path) -> dict[str, str | list[str] | None]:
    tree: dict[str, str | list[str] | None] = {}
    for path in sorted(root.rglob('*')):
        name = path.relative_to(root).as_posix()
        if path.is_dir():
            tree[name + '/'] = None
        elif path.name == 'LICENSE':
            tree[name] = ['sha256:' + hashlib.sha256(path.read_bytes()).hexdigest()]
        else:
            tree[name] = path.read_text(encoding='utf-8')
    return tree


@pytest.mark.parametrize('case', sorted(CREATE_EXPECTED))
def test_create_writes_jazzys_files(tmp_path, case):
    expected = CREATE_EXPECTED[case]
    result = _create(tmp_path, *expected['args'])
    assert (result.returncode, result.stderr) == (expected['rc'], expected['stderr'])
    assert result.stdout.replace(str(tmp_path), '<CWD>') == expected['stdout']
    assert _tree(tmp_path) == expected['tree']


LICENSE_WARNING = """
[WARNING]: Unknown license 'TODO: License declaration'.  This has been set in the package.xml, \
but no LICENSE file has been created.
It is recommended to use one of the ament license identifiers:
"""
LICENSES = 'Apache-2.0\nBSL-1.0\nBSD-2.0\nBSD-2-Clause\nBSD-3-Clause\nGPL-3.0-only\n' \
           'LGPL-3.0-only\nMIT\nMIT-0\n'


def test_create_license_list_and_unknown_license(tmp_path):
    result = _create(tmp_path, 'x', '--license', '?')
    assert (result.returncode, result.stdout, list(tmp_path.iterdir())) == \
        (0, 'Supported licenses:\n' + LICENSES, [])
    result = _create(tmp_path, 'x', '--maintainer-name', 'a', '--maintainer-email', 'b')
    assert result.returncode == 0
    assert result.stdout.endswith('creating ./x/CMakeLists.txt\n' + LICENSE_WARNING + LICENSES)
    assert not (tmp_path / 'x' / 'LICENSE').exists()


def test_create_refuses_an_existing_folder(tmp_path):
    (tmp_path / 'x').mkdir()
    result = _create(tmp_path, 'x', '--node-name', 'a', '--library-name', 'a')
    assert (result.returncode, result.stdout, result.stderr) == (1, '', (
        '[WARNING] node name can not be equal to the library name\n'
        '[WARNING] renaming node to a_node\n\nAborted!\nThe directory already exists: ./x\n'
        'Either remove the directory or choose a different destination directory or package '
        'name\n'))
    assert list((tmp_path / 'x').iterdir()) == []


@pytest.mark.parametrize(('args', 'error'), [
    (['x', '--build-type', 'catkin'], "argument --build-type: invalid choice: 'catkin' "
                                      "(choose from 'cmake', 'ament_cmake', 'ament_python')"),
    (['x', '--package-format', '1'], 'argument --package-format/--package_format: invalid '
                                     'choice: 1 (choose from 2, 3)'),
    (['x', '--dependencies'], 'argument --dependencies: expected at least one argument'),
    (['--dependencies', 'a', 'x'], 'the following arguments are required: package_name'),
])
def test_create_usage_errors(tmp_path, args, error):
    result = _create(tmp_path, *args)
    assert (result.returncode, result.stderr.splitlines()[-1]) == \
        (2, f'ros2 pkg create: error: {error}')
    assert result.stderr.startswith('usage: ros2 pkg create [-h] [--package-format {2,3}]\n')


def _maintainer(tmp_path: Path, *args: str, env: dict[str, str],
                cwd: Path | None = None) -> tuple[str, str]:
    result = _create(tmp_path, 'x', *args, env=env, cwd=cwd)
    root = (cwd or tmp_path) / 'x'
    line = next(line for line in (root / 'package.xml').read_text().splitlines()
                if '<maintainer' in line)
    shutil.rmtree(root)
    return result.stdout.splitlines()[6], line.strip()


def test_create_maintainer_from_the_environment(tmp_path):
    """As observed on Jazzy: the login name (LOGNAME before USER), the email from
    `git config user.email` where the command runs, else `<maintainer>@todo.todo`."""
    home = tmp_path / 'home'
    home.mkdir()
    no_git_config = {'HOME': str(home), 'XDG_CONFIG_HOME': str(home),
                     'GIT_CONFIG_NOSYSTEM': '1', 'LOGNAME': 'bob', 'USER': 'alice'}
    assert _maintainer(tmp_path, env=no_git_config) == (
        "maintainer: ['bob <bob@todo.todo>']", '<maintainer email="bob@todo.todo">bob</maintainer>')
    assert _maintainer(tmp_path, '--maintainer-name', 'Ann Ex', '--maintainer-email', '',
                       env=no_git_config)[1] == \
        '<maintainer email="Ann Ex@todo.todo">Ann Ex</maintainer>'
    repo = tmp_path / 'repo'
    subprocess.run(['git', 'init', '-q', str(repo)], check=True,
                   env={**os.environ, **no_git_config})
    subprocess.run(['git', 'config', 'user.email', 'local@x.org'], cwd=repo, check=True)
    assert _maintainer(tmp_path, env=no_git_config, cwd=repo)[1] == \
        '<maintainer email="local@x.org">bob</maintainer>'
    without_git = {**no_git_config, 'PATH': str(Path(ROS2).parent)}
    assert _maintainer(tmp_path, env=without_git, cwd=repo)[1] == \
        '<maintainer email="bob@todo.todo">bob</maintainer>'


def test_created_python_package_builds_with_colcon(tmp_path):
    colcon = Path(sys.executable).with_name('colcon')
    if not colcon.exists():
        pytest.skip('colcon is not installed')
    result = _create(tmp_path / 'src', 'demo_py', '--build-type', 'ament_python',
                     '--node-name', 'hello', '--maintainer-email', 'a@b.c')
    assert result.returncode == 0
    build = subprocess.run([str(colcon), 'build', '--packages-select', 'demo_py'], cwd=tmp_path,
                           capture_output=True, text=True, timeout=120)
    assert build.returncode == 0, build.stderr
    assert (tmp_path / 'install' / 'demo_py' / 'lib' / 'demo_py' / 'hello').exists()
