"""Fixtures of the launch_ros tests: a private ROS domain, a colcon-built
package, a way to run a launch in-process and record what it started, and
a session-end check that no process started by the tests survived.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import uuid
from collections.abc import Iterator
from pathlib import Path

import psutil
import pytest
from launch_testing.domain_isolation import lease_domain

HERE = Path(__file__).parent
TOKEN_VAR = 'LAUNCH_ROS_TEST_TOKEN'


def _processes_with_token(token: str) -> list[psutil.Process]:
    found = []
    for proc in psutil.process_iter():
        if proc.pid == os.getpid():
            continue
        try:
            if proc.environ().get(TOKEN_VAR) == token:
                found.append(proc)
        except (psutil.AccessDenied, psutil.NoSuchProcess, psutil.ZombieProcess):
            continue
    return found


class DomainLease:
    """One locked ROS domain ID and the token marking the processes started under it."""

    def __init__(self) -> None:
        self._lease = lease_domain()
        self.domain_id = self._lease.domain_id
        self.token = uuid.uuid4().hex

    def env(self) -> dict[str, str]:
        return {'ROS_DOMAIN_ID': str(self.domain_id),
                'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST', TOKEN_VAR: self.token}

    def release(self) -> None:
        self._lease.release()


@pytest.fixture(scope='session')
def domain_lease() -> Iterator[DomainLease]:
    """A private ROS domain for these tests; at the end, no process may carry its token."""
    lease = DomainLease()
    try:
        yield lease
    finally:
        leftovers = _processes_with_token(lease.token)
        for proc in leftovers:
            proc.kill()
        lease.release()
        assert not leftovers, f'processes left behind by the launch_ros tests: {leftovers}'


@pytest.fixture(autouse=True)
def ros_isolation(domain_lease: DomainLease, monkeypatch: pytest.MonkeyPatch) -> int:
    """Put each test (and every process it starts) in the private domain.

    Set per test with monkeypatch so that tests outside this folder, run in
    the same session, see the environment they expect.
    """
    for key, value in domain_lease.env().items():
        monkeypatch.setenv(key, value)
    monkeypatch.delenv('ROS_LOCALHOST_ONLY', raising=False)
    return domain_lease.domain_id


@pytest.fixture(scope='session')
def built_package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Build fixture_pkg/lr_test_pkg with colcon once; return its install prefix."""
    ws = tmp_path_factory.mktemp('ws')
    shutil.copytree(HERE / 'fixture_pkg', ws / 'src')
    colcon = shutil.which('colcon', path=os.path.dirname(sys.executable)) or 'colcon'
    subprocess.run([colcon, 'build'], cwd=ws, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.STDOUT, timeout=120)
    return ws / 'install' / 'lr_test_pkg'


@pytest.fixture
def test_package(built_package: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The built package, made findable as `source install/setup.bash` would.

    Its prefix goes on AMENT_PREFIX_PATH (ament index) and its site-packages
    on PYTHONPATH (console scripts).
    """
    site = next(built_package.glob('lib/python3*/site-packages'))
    for var, value in (('AMENT_PREFIX_PATH', built_package), ('PYTHONPATH', site)):
        old = os.environ.get(var)
        monkeypatch.setenv(var, str(value) + (os.pathsep + old if old else ''))
    return built_package


class LaunchRecord:
    """What one in-process launch did: its exit code and the processes it started."""

    def __init__(self) -> None:
        self.returncode: int | None = None
        self.processes: list[dict] = []

    def by_name(self, prefix: str) -> dict:
        """The process whose `name-N` starts with `prefix-`."""
        matches = [p for p in self.processes if p['name'].rsplit('-', 1)[0] == prefix]
        assert len(matches) == 1, (prefix, [p['name'] for p in self.processes])
        return matches[0]

    def node_cmd(self, node_name: str) -> list:
        """The command line of the process started with `-r __node:=node_name`."""
        matches = [p['cmd'] for p in self.processes if '__node:=' + node_name in p['cmd']]
        assert len(matches) == 1, (node_name, [p['cmd'] for p in self.processes])
        return matches[0]


def _read_param_files(cmd: list[str]) -> list:
    """Replace each `--params-file PATH` by {'path': PATH, 'content': parsed YAML}.

    Read while the process starts, since temporary files go away with the launch.
    """
    import yaml

    out, i = [], 0
    while i < len(cmd):
        if cmd[i] == '--params-file' and i + 1 < len(cmd):
            path = cmd[i + 1]
            try:
                with open(path) as handle:
                    content = yaml.safe_load(handle)
            except OSError as exc:
                content = f'unreadable: {exc.strerror}'
            out += ['--params-file', {'path': path, 'content': content}]
            i += 2
        else:
            out.append(cmd[i])
            i += 1
    return out


@pytest.fixture
def run_launch():
    """Run entities in a LaunchService in this process; return a LaunchRecord.

    With `shutdown_after=None` the launch ends when idle (every process
    exited); otherwise a Shutdown is emitted after that many seconds.  The
    record is checked for processes that outlived the launch.
    """
    from launch import LaunchDescription, LaunchService
    from launch.actions import EmitEvent, RegisterEventHandler, TimerAction
    from launch.event_handlers import OnProcessStart
    from launch.events import Shutdown

    def run(entities: list, *, argv: tuple = (), shutdown_after: float | None = None,
            ) -> LaunchRecord:
        record = LaunchRecord()

        def on_start(event, context):
            record.processes.append({
                'name': event.process_name, 'pid': event.pid,
                'cmd': _read_param_files([str(t) for t in event.cmd]),
                'env': dict(event.env or {})})

        extra = [] if shutdown_after is None else [
            TimerAction(period=shutdown_after, actions=[EmitEvent(event=Shutdown())])]
        service = LaunchService(argv=list(argv))
        service.include_launch_description(LaunchDescription(
            [RegisterEventHandler(OnProcessStart(on_start=on_start)), *entities, *extra]))
        record.returncode = service.run()
        alive = [p for p in record.processes if psutil.pid_exists(p['pid'])
                 and psutil.Process(p['pid']).status() != psutil.STATUS_ZOMBIE]
        assert not alive, f'processes outlived the launch: {alive}'
        return record

    return run
