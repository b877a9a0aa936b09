"""When the probe judges a launch to be up: not before a launch that pauses
between its processes has started the expected nodes (on a fake clock); and
a launch that should have refused to start is stopped at its first process."""
from __future__ import annotations

from pathlib import Path

from labkit.grading import launch_probe
from labkit.grading.student_package import StudentPackage
from labkit.graph import GraphSnapshot


class _Clock:
    def __init__(self) -> None:
        self.now = 0.0

    def monotonic(self) -> float:
        return self.now

    def sleep(self, seconds: float) -> None:
        self.now += seconds


class _Launch:
    """A launch whose log and graph grow on a schedule: (time, log line, node)."""

    command = 'ros2 launch pkg bringup.launch.py'

    def __init__(self, clock: _Clock, schedule: list[tuple[float, str, str | None]]) -> None:
        self.clock, self.schedule = clock, schedule

    def _due(self) -> list[tuple[float, str, str | None]]:
        return [event for event in self.schedule if event[0] <= self.clock.now]

    @property
    def lines(self) -> list[str]:
        return [line for _, line, _ in self._due()]

    def nodes(self) -> list[str]:
        return [node for _, _, node in self._due() if node]

    def poll(self) -> None:
        return None

    def stop(self) -> int:
        return 0


def _probe(monkeypatch, schedule: list[tuple[float, str, str | None]],
           expected: tuple[str, ...], **options: bool) -> tuple[launch_probe.LaunchProbe, float]:
    clock = _Clock()
    running = _Launch(clock, schedule)
    monkeypatch.setattr(launch_probe, 'time', clock)
    monkeypatch.setattr(launch_probe, 'launch', lambda *args, **kwargs: running)
    monkeypatch.setattr(launch_probe.observer, 'node_names', running.nodes)
    monkeypatch.setattr(launch_probe, 'graph',
                        lambda: GraphSnapshot(tuple(sorted(running.nodes())), {}))
    package = StudentPackage(Path('/nowhere'), 'pkg')
    monkeypatch.setattr(StudentPackage, 'environment', lambda self: {})
    run = launch_probe.probe(package, 'bringup.launch.py', expected, timeout=60, **options)
    return run, clock.now


def _started(t: float, process: str, node: str) -> list[tuple[float, str, str | None]]:
    return [(t, f'[INFO] [{process}]: process started with pid [{int(t * 10) + 100}]', None),
            (t + 0.2, f'[{process}] [INFO] [{t + 0.2:.1f}] [{node}]: ready', f'/{node}')]


SLOW_INCLUDE = _started(0.0, 'turtlesim-1', 'turtlesim') + _started(3.0, 'controller-2',
                                                                    'controller')


def test_a_launch_that_pauses_between_processes_is_judged_once_the_expected_nodes_are_up(
        monkeypatch):
    run, at = _probe(monkeypatch, SLOW_INCLUDE, ('/turtlesim', '/controller'))
    assert run.nodes == ('/controller', '/turtlesim')
    assert at < 4.0  # judged as soon as both were there


def test_a_node_that_never_comes_is_given_up_on_after_the_longer_settle(monkeypatch):
    run, at = _probe(monkeypatch, SLOW_INCLUDE, ('/turtlesim', '/controller', '/camera'))
    assert run.nodes == ('/controller', '/turtlesim')  # the late include was waited for
    assert 3.0 + launch_probe.PROCESSES_SETTLED_WITH_NODES_MISSING <= at < 60


def test_without_expected_nodes_a_short_settle_suffices(monkeypatch):
    run, at = _probe(monkeypatch, _started(0.0, 'turtlesim-1', 'turtlesim'), ())
    assert run.nodes == ('/turtlesim',)
    assert at < 0.2 + 2 * launch_probe.PROCESSES_SETTLED


def test_until_first_process_stops_at_the_first_process_without_a_graph(monkeypatch):
    run, at = _probe(monkeypatch, SLOW_INCLUDE, ('/turtlesim', '/controller'),
                     until_first_process=True)
    assert run.processes == ['turtlesim-1']
    assert run.snapshot is None and not run.exited_by_itself
    assert at < 0.2  # before its node logged, long before the whole launch is up


def test_a_node_whose_process_has_finished_is_not_waited_for(monkeypatch):
    # The capstone's spawner logs as /turtle2/spawner, spawns, and exits: its node is
    # never in the graph the probe reads, and the launch is up without it.
    spawner = [(0.0, '[INFO] [spawner-1]: process started with pid [100]', None),
               (0.1, '[spawner-1] [INFO] [0.1] [turtle2.spawner]: spawned turtle2', None),
               (0.2, '[INFO] [spawner-1]: process has finished cleanly [pid 100]', None)]
    run, at = _probe(monkeypatch, spawner + _started(0.3, 'turtlesim-2', 'turtlesim'),
                     ('/turtlesim',))
    assert run.nodes == ('/turtlesim',)
    assert at < 2.0  # not the whole timeout
