"""`ros2 component ...` in Jazzy's words (outputs recorded from the Jazzy reference).

The headless stack has no C++ component container, so list/load/unload talk
to a fake rclpy container (fake_container.py) through a stand-in for
composition_interfaces (interface_stand_in.py); the reference answered the
same commands against the same fake container.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from cli_processes import stop_process
from interface_stand_in import environment

ROS2 = str(Path(sys.executable).with_name('ros2'))
FAKE_CONTAINER = str(Path(__file__).with_name('fake_container.py'))

LOAD_HELP_HEAD = """\
usage: ros2 component load [-h] [--spin-time SPIN_TIME] [-s] [--no-daemon]
                           [-n NODE_NAME] [--node-namespace NODE_NAMESPACE]
                           [--log-level LOG_LEVEL] [-r REMAP_RULES]
                           [-p PARAMETERS] [-e EXTRA_ARGUMENTS] [-q]
                           container_node_name package_name plugin_name
"""


@pytest.fixture(scope='module')
def comp_env(cli_env):
    return environment(cli_env)


@pytest.fixture(scope='module')
def component(comp_env):
    def run(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
        return subprocess.run([ROS2, 'component', *args], env={**comp_env, **(env or {})},
                              capture_output=True, text=True, timeout=60)
    return run


@pytest.fixture(scope='module')
def container(comp_env):
    proc = subprocess.Popen([sys.executable, FAKE_CONTAINER, 'my_container'], env=comp_env,
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                            start_new_session=True)
    try:
        assert proc.stdout.readline() == 'ready\n'
        yield proc
    finally:
        stop_process(proc)


def _result(result: subprocess.CompletedProcess) -> tuple[int, str, str]:
    return result.returncode, result.stdout, result.stderr


def test_load_help(component):
    assert component('load', '-h', env={'COLUMNS': '80'}).stdout.startswith(LOAD_HELP_HEAD)


def test_types_from_the_ament_index(component, tmp_path):
    """Each line's part before `;`, blank lines too; an unknown package is an error."""
    index = tmp_path / 'share' / 'ament_index' / 'resource_index'
    (index / 'packages').mkdir(parents=True)
    (index / 'rclcpp_components').mkdir()
    (index / 'packages' / 'pkg_b').touch()
    (index / 'rclcpp_components' / 'pkg_b').write_text(
        'pkg_b::Zeta;lib/libz.so\n\nnosemicolon\npkg_b::Alpha;lib/liba.so;extra\n')
    env = {'AMENT_PREFIX_PATH': str(tmp_path)}
    assert _result(component('types', env=env)) == (
        0, 'pkg_b\n  pkg_b::Zeta\n  \n  nosemicolon\n  pkg_b::Alpha\n', '')
    assert _result(component('types', 'pkg_b', env=env)) == (
        0, 'pkg_b::Zeta\n\nnosemicolon\npkg_b::Alpha\n', '')
    assert _result(component('types', 'nonexist', env=env)) == (
        1, '', "Unable to find package 'nonexist'\n")


def test_standalone_without_rclcpp_components(component):
    assert _result(component('standalone', 'demo_nodes_cpp', 'demo_nodes_cpp::Talker')) == (
        1, '', "Package 'rclcpp_components' not found\n")


def test_no_such_container(component, container):
    assert _result(component('load', '/nope', 'a', 'b::C')) == (
        1, '', "Unable to find container node '/nope'\n")
    assert _result(component('list', 'my_container')) == (
        1, '', "Unable to find container node 'my_container'\n")


def test_load_list_unload(component, container):
    assert _result(component('load', '/my_container', 'demo_nodes_cpp',
                             'demo_nodes_cpp::Talker')) == (
        0, "Loaded component 1 into '/my_container' container node as '/talker'\n", '')
    assert _result(component('load', '/my_container', 'p', 'a::B', '-n', 'lis',
                             '--node-namespace', '/ns', '-r', 'a:=b', '-p', 'x:=1', '-q')) == (
        0, '2  /ns/lis\n', '')
    assert _result(component('load', '/my_container', 'bad', 'x::Y')) == (
        1, '', 'Failed to load component: Could not find requested resource in ament index\n')
    assert _result(component('list')) == (0, '/my_container\n  1  /talker\n  2  /ns/lis\n', '')
    assert _result(component('list', '/my_container')) == (0, '1  /talker\n2  /ns/lis\n', '')
    assert _result(component('list', '--containers-only')) == (0, '/my_container\n', '')
    assert _result(component('unload', '/my_container', '1', '7')) == (
        1, "Unloaded component 1 from '/my_container' container node\n",
        "Failed to unload component 7 from '/my_container' container node\n"
        '    No node found with unique_id: 7\n')
    assert _result(component('unload', '/my_container', '2', '-q')) == (0, '2\n', '')
    assert _result(component('list', '/my_container')) == (0, '', '')
