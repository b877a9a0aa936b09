"""Launch files of lesson 6.13 (configuration management) start the nodes,
namespaces and parameters the lesson says, for every robot and site it
picks, and the layering mistakes it shows give the values it shows.

Each launch is started as the lesson starts it (``ros2 launch rover_config
rover.launch.py name:=value``, through labkit); its nodes are awaited, the
graph is read until it shows the expected wiring, every node's parameters
are read over its parameter services, and the launch is stopped with Ctrl+C.
The new site (``incoming/sites/warehouse.yaml``) is added to a copy of the
package in a scratch workspace, as the lesson adds it, and must leave the
launch interface (``--show-args``) as it was.
"""
from __future__ import annotations

import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import labkit
import pytest
from labkit.grading.student_package import StudentPackage
from textbook import paths
from textbook.myst import fences

from ._launch_log import ENDED, STARTED
from ._wiring import Wiring, in_namespace, nodes_in, settled_graph, wiring

LESSON = paths.LESSONS / 'ch06/L3/13_configuration_management.md'
PACKAGE = 'rover_config'
SOURCE = paths.SNIPPETS / PACKAGE
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
NODES = ('sensor_publisher', 'data_processor', 'robot_controller')


@dataclass(frozen=True)
class Case:
    """One launch of rover.launch.py as the lesson runs it, and what its nodes get."""

    arguments: dict[str, str]
    robot: str
    #: (node, parameter) -> value (and type) the running node must report
    expected: dict[tuple[str, str], Any]

    @property
    def id(self) -> str:
        return ' '.join(f'{k}:={v}' for k, v in self.arguments.items()) or 'defaults'


def _rover(robot: str, publish_rate: float, window_size: int, update_rate: float,
           max_linear_speed: float, max_angular_speed: float, sim_time: bool = False
           ) -> dict[tuple[str, str], Any]:
    """Every value the lesson reads from one rover's three nodes."""
    expected: dict[tuple[str, str], Any] = {
        ('sensor_publisher', 'publish_rate'): publish_rate,
        ('data_processor', 'window_size'): window_size,
        ('robot_controller', 'robot_name'): robot,
        ('robot_controller', 'update_rate'): update_rate,
        ('robot_controller', 'max_linear_speed'): max_linear_speed,
        ('robot_controller', 'max_angular_speed'): max_angular_speed,
    }
    expected.update({(node, 'use_sim_time'): sim_time for node in NODES})
    return expected


CASES = [
    # defaults < scout < lab: the lab's limits win, scout's rates stay.
    Case({}, 'scout', _rover('scout', 10.0, 5, 20.0, 0.3, 0.5)),
    # ranger at the field: the field only smooths; ranger's own speed.
    Case({'robot': 'ranger', 'site': 'field'}, 'ranger', _rover('ranger', 2.0, 9, 15.0, 0.8, 1.0)),
    # SetParameter: one global for all three nodes.
    Case({'use_sim_time': 'true'}, 'scout', _rover('scout', 10.0, 5, 20.0, 0.3, 0.5, True)),
    # Fully qualified robot keys: the lab's speed is lost, its angular limit is not.
    Case({'robot': 'explorer'}, 'explorer', _rover('explorer', 10.0, 5, 20.0, 1.5, 0.5)),
    # A /** site section: applied before the robot's sections, so nothing of it shows.
    Case({'site': 'lab_everywhere'}, 'scout', _rover('scout', 10.0, 5, 20.0, 1.2, 2.0)),
]


def _wiring_of(case: Case) -> Wiring:
    ns = f'/{case.robot}'
    topics: Wiring = {
        f'{ns}/distance': ((f'{ns}/sensor_publisher',), (f'{ns}/data_processor',)),
        f'{ns}/distance_filtered': ((f'{ns}/data_processor',), (f'{ns}/robot_controller',)),
        f'{ns}/cmd_vel': ((f'{ns}/robot_controller',), ())}
    if case.expected[('sensor_publisher', 'use_sim_time')]:  # each node then reads /clock
        topics['/clock'] = ((), tuple(sorted(f'{ns}/{node}' for node in NODES)))
    return topics


def _typed(values: dict[tuple[str, str], Any]) -> dict[tuple[str, str], tuple[str, Any]]:
    """(node, name) -> (type, value): 5 and 5.0 are different answers here."""
    return {key: (type(value).__name__, value) for key, value in values.items()}


def _run_and_read(case: Case, env: dict[str, str], cwd: Path) -> tuple[str, dict, Any, int]:
    """(output, parameters read, graph, exit code) of one launch of rover.launch.py."""
    nodes = [f'/{case.robot}/{node}' for node in NODES]
    with labkit.launch(PACKAGE, 'rover.launch.py', launch_arguments=case.arguments, env=env,
                       cwd=cwd) as run:
        run.wait_for_nodes(nodes, timeout=HANG_GUARD)
        snapshot = settled_graph(_wiring_of(case), HANG_GUARD, namespace=f'/{case.robot}')
        parameters = {node: labkit.read_parameters(f'/{case.robot}/{node}') for node in NODES}
        got = {(node, name): parameters[node].get(name) for node, name in case.expected}
        assert run.running, run.output()
        exit_code = run.stop()
    return run.output(), got, snapshot, exit_code


def _assert_system(case: Case, output: str, got: dict, snapshot: Any, exit_code: int) -> None:
    assert 'process has died' not in output, output
    started = [m.group(1) for line in output.splitlines() if (m := STARTED.match(line))]
    assert sorted(started) == sorted(NODES), output
    # Only this launch's namespace: see _wiring.in_namespace.
    namespace = f'/{case.robot}'
    assert nodes_in(snapshot, namespace) == sorted(f'{namespace}/{node}' for node in NODES), output
    assert in_namespace(wiring(snapshot), namespace) == _wiring_of(case), str(snapshot)
    assert _typed(got) == _typed(case.expected)
    ended = [m.group(1) for line in output.splitlines() if (m := ENDED.match(line))]
    assert exit_code == 0 and sorted(ended) == sorted(started), output


@pytest.mark.parametrize('case', CASES, ids=lambda case: case.id)
def test_rover_gets_the_layered_values_the_lesson_shows(case: Case, ros_env):
    _assert_system(case, *_run_and_read(case, ros_env, paths.WORKSPACE))


def test_set_parameter_comes_before_the_layers_on_the_node_command_line(ros_env):
    """The lesson's explanation of the lost /** section: -p use_sim_time:=... comes first."""
    with labkit.launch(PACKAGE, 'rover.launch.py', env=ros_env, cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(['/scout/robot_controller'], timeout=HANG_GUARD)
        listing = subprocess.run(['ps', '-ww', '-o', 'args', '--ppid', str(run.pid)],
                                 capture_output=True, text=True, check=True).stdout
    controller = next(line for line in listing.splitlines() if 'robot_controller' in line)
    words = controller.split()
    assert words.count('--params-file') == 3, controller
    assert words.index('-p') < words.index('--params-file'), controller
    assert words[words.index('-p') + 1] == 'use_sim_time:=False', controller
    assert '/share/rover_config/config/robots/scout.yaml' in controller, controller
    assert controller.rstrip().endswith('/share/rover_config/config/sites/lab.yaml'), controller


def test_set_parameters_from_file_is_a_layer_below_the_nodes_own(ros_env):
    """SetParametersFromFile's file comes first on the node's command line, so scout's
    own speeds (robots/scout.yaml) beat the lab's limits, as the lesson shows."""
    with labkit.launch(PACKAGE, 'rover_site_for_the_group.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as run:
        run.wait_for_nodes(['/scout/robot_controller'], timeout=HANG_GUARD)
        values = labkit.read_parameters('/scout/robot_controller')
        listing = subprocess.run(['ps', '-ww', '-o', 'args', '--ppid', str(run.pid)],
                                 capture_output=True, text=True, check=True).stdout
    assert (values['max_linear_speed'], values['max_angular_speed']) == (1.2, 2.0), values
    words = next(line for line in listing.splitlines() if 'robot_controller' in line).split()
    files = [words[i + 1] for i, word in enumerate(words) if word == '--params-file']
    assert len(files) == 3 and files[0].endswith('/share/rover_config/config/sites/lab.yaml'), \
        files
    assert files[2].endswith('/share/rover_config/config/robots/scout.yaml'), files


def _ros2(env: dict[str, str], cwd: Path, *words: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(['ros2', *words], env=env, cwd=cwd, capture_output=True, text=True,
                          timeout=120, check=False)


def test_a_new_site_keeps_the_interface_and_applies(tmp_path, ros_env):
    """As the lesson does: copy incoming/sites/warehouse.yaml into config/sites/, rebuild."""
    before = _ros2(ros_env, paths.WORKSPACE, 'launch', PACKAGE, 'rover.launch.py', '--show-args')
    assert before.returncode == 0 and "'site':" in before.stdout, before
    package = tmp_path / 'src' / PACKAGE
    shutil.copytree(SOURCE, package, ignore=shutil.ignore_patterns('__pycache__'))
    installed = paths.WORKSPACE / 'install' / PACKAGE / 'share' / PACKAGE
    assert not (installed / 'config' / 'sites' / 'warehouse.yaml').exists()  # not shipped yet
    shutil.copy(package / 'incoming' / 'sites' / 'warehouse.yaml', package / 'config' / 'sites')
    build = subprocess.run([paths.executable('colcon'), 'build'], cwd=tmp_path, env=ros_env,
                           capture_output=True, text=True, timeout=600, check=False)
    assert build.returncode == 0, build.stdout + build.stderr
    env = StudentPackage(tmp_path, PACKAGE).environment(ros_env)
    after = _ros2(env, tmp_path, 'launch', PACKAGE, 'rover.launch.py', '--show-args')
    assert after.returncode == 0 and after.stdout == before.stdout, after
    case = Case({'site': 'warehouse'}, 'scout', _rover('scout', 5.0, 5, 20.0, 0.4, 2.0))
    _assert_system(case, *_run_and_read(case, env, tmp_path))


def test_show_args_lists_the_three_arguments(ros_env):
    shown = _ros2(ros_env, paths.WORKSPACE, 'launch', PACKAGE, 'rover.launch.py', '--show-args')
    assert shown.returncode == 0, shown
    for name, default in (('robot', 'scout'), ('site', 'lab'), ('use_sim_time', 'false')):
        assert f"    '{name}':" in shown.stdout and f"(default: '{default}')" in shown.stdout
    assert shown.stdout.count("':\n") == 3, shown.stdout


def _rover_config_files_shown(lesson: Path) -> set[str]:
    """Files of rover_config (path inside the package) the lesson includes."""
    found = set()
    for fence in fences(lesson.read_text()):
        target = fence.argument.partition('#')[0]
        if fence.directive == 'snippet' and target.startswith(f'{PACKAGE}/'):
            found.add(target.removeprefix(f'{PACKAGE}/'))
    return found


#: Every configuration a case above loads, and the launch file they all run.
TESTED = {'launch/rover.launch.py', 'launch/rover_site_for_the_group.launch.py',
          'config/defaults.yaml', 'config/robots/scout.yaml',
          'config/robots/ranger.yaml', 'config/robots/explorer.yaml', 'config/sites/lab.yaml',
          'config/sites/field.yaml', 'config/sites/lab_everywhere.yaml',
          'incoming/sites/warehouse.yaml', 'setup.py', 'package.xml'}


def test_every_file_of_rover_config_the_lesson_shows_is_tested():
    shown = _rover_config_files_shown(LESSON)
    assert 'launch/rover.launch.py' in shown, shown
    assert shown <= TESTED, f'shown but not tested: {sorted(shown - TESTED)}'


def test_every_configuration_of_rover_config_is_tested():
    files = {str(path.relative_to(SOURCE)) for path in SOURCE.rglob('*')
             if path.suffix in ('.yaml', '.py') and path.name != 'setup.py'}
    assert files and files <= TESTED, sorted(files - TESTED)
