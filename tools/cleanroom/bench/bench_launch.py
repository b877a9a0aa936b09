"""Benchmark the clean-room launch: start and stop N talker nodes.

    .venv/bin/python tools/cleanroom/bench/bench_launch.py [--counts 1 10 30] [--repeat 3]

For each N the script launches N rclpy talkers (launch_ros Node actions) and
measures, from the moment LaunchService.run() is called:

  started   every process has been started (its ProcessStarted event),
  ready     every talker has created its publisher (it logs 'ready'),
  shutdown  a Shutdown emitted once all are ready has stopped every process,
            i.e. start to clean shutdown (each process must exit with code 0).

It also reports the CPU time used by the launch process itself and by the
talkers: on 2 cores the rclpy talkers' own start-up and tear-down (about
0.3-0.5 s of CPU each) bound 'ready' and 'shutdown', not the launch.

Two references: the figures of real ROS 2 Jazzy's launch on a 2-core machine
(measured elsewhere, with its own talkers), and a floor measured in the same
run: the same talker command lines started with plain subprocess.Popen,
waited on until ready, then sent SIGINT, with no launch at all.  The ratio
ours / floor is what our launch adds on this machine (1.00 = nothing); the
ratio ours / Jazzy compares absolute times across machines and talkers.

The talker comes from a tiny ament_python package the script writes to a
temporary folder and builds with colcon (the colcon next to this Python).
Runs get a ROS domain from the lock-file allocator of CONTRIBUTING.md and
LOCALHOST discovery, and a temporary ROS_LOG_DIR.
"""
from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from launch_testing.domain_isolation import lease_domain

# Jazzy on a 2-core machine: N -> (all started, start to clean shutdown), seconds.
REFERENCE: dict[int, tuple[float | None, float | None]] = {
    10: (0.11, None),
    30: (0.88, 3.6),
}

TALKER = """
import sys

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init(args=sys.argv)
    node = Node('talker')
    publisher = node.create_publisher(String, 'chatter', 10)
    count = [0]

    def tick():
        count[0] += 1
        publisher.publish(String(data='hello %d' % count[0]))

    node.create_timer(0.1, tick)
    try:  # Ctrl-C may come as soon as 'ready' is out
        node.get_logger().info('ready')
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
"""

SETUP_PY = """
from setuptools import setup

setup(
    name='bench_pkg', version='0.0.1', packages=['bench_pkg'],
    data_files=[('share/ament_index/resource_index/packages', ['resource/bench_pkg']),
                ('share/bench_pkg', ['package.xml'])],
    entry_points={'console_scripts': ['talker = bench_pkg.talker:main']},
)
"""

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>bench_pkg</name>
  <version>0.0.1</version>
  <description>Talker for the launch benchmark</description>
  <maintainer email="nobody@example.com">nobody</maintainer>
  <license>Apache-2.0</license>
  <exec_depend>rclpy</exec_depend>
  <exec_depend>std_msgs</exec_depend>
  <export><build_type>ament_python</build_type></export>
</package>
"""


def build_talker_package(root: Path) -> Path:
    """Write and colcon-build bench_pkg below `root`; return its install prefix."""
    src = root / 'src' / 'bench_pkg'
    (src / 'bench_pkg').mkdir(parents=True)
    (src / 'resource').mkdir()
    (src / 'resource' / 'bench_pkg').write_text('')
    (src / 'bench_pkg' / '__init__.py').write_text('')
    (src / 'bench_pkg' / 'talker.py').write_text(TALKER)
    (src / 'setup.py').write_text(SETUP_PY)
    (src / 'setup.cfg').write_text('[install]\ninstall_scripts=$base/lib/bench_pkg\n')
    (src / 'package.xml').write_text(PACKAGE_XML)
    colcon = shutil.which('colcon', path=os.path.dirname(sys.executable)) or 'colcon'
    subprocess.run([colcon, 'build'], cwd=root, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, timeout=300)
    return root / 'install' / 'bench_pkg'


def use_prefix(prefix: Path) -> None:
    """Make the package findable, as sourcing its setup.bash would."""
    site = next(prefix.glob('lib/python3*/site-packages'))
    for var, value in (('AMENT_PREFIX_PATH', prefix), ('PYTHONPATH', site)):
        old = os.environ.get(var)
        os.environ[var] = str(value) + (os.pathsep + old if old else '')


def run_once(count: int) -> dict[str, float]:
    """Launch `count` talkers, shut down when all are ready; return the timings."""
    import launch
    import launch.logging
    from launch.actions import RegisterEventHandler, Shutdown
    from launch.event_handlers import OnProcessExit, OnProcessIO, OnProcessStart
    from launch_ros.actions import Node

    launch.logging.reset()
    marks: dict[str, float] = {}
    started: list[int] = []
    ready: set = set()
    exit_codes: list[int] = []

    def on_start(event: object, context: object) -> None:
        started.append(event.pid)
        if len(started) == count:
            marks['started'] = time.monotonic()

    def on_stderr(event: object) -> list | None:
        if b'ready' in event.text:
            ready.add(event.pid)
            if len(ready) == count and 'ready' not in marks:
                marks['ready'] = time.monotonic()
                return [Shutdown(reason='benchmark: all talkers ready')]
        return None

    nodes = [Node(package='bench_pkg', executable='talker', name=f'talker_{i}')
             for i in range(count)]
    service = launch.LaunchService()
    service.include_launch_description(launch.LaunchDescription([
        RegisterEventHandler(OnProcessStart(on_start=on_start)),
        RegisterEventHandler(OnProcessIO(on_stderr=on_stderr)),
        RegisterEventHandler(OnProcessExit(
            on_exit=lambda event, context: exit_codes.append(event.returncode))),
        *nodes,
    ]))
    cpu_self = _cpu(resource.RUSAGE_SELF)
    cpu_children = _cpu(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    code = service.run()
    marks['shutdown'] = time.monotonic()
    cpu = {'launch_cpu': _cpu(resource.RUSAGE_SELF) - cpu_self,
           'nodes_cpu': _cpu(resource.RUSAGE_CHILDREN) - cpu_children}
    if code != 0 or len(exit_codes) != count or any(exit_codes) or len(ready) != count:
        raise RuntimeError(f'N={count}: launch exit {code}, process exit codes {exit_codes}, '
                           f'{len(ready)} ready')
    return {**{key: value - t0 for key, value in marks.items()}, **cpu}


def run_direct(count: int, executable: str) -> dict[str, float]:
    """The floor: start the same talker command lines without launch, stop with SIGINT."""
    import selectors
    import signal

    t0 = time.monotonic()
    procs = [subprocess.Popen([executable, '--ros-args', '-r', f'__node:=talker_{i}'],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
             for i in range(count)]
    marks = {'started': time.monotonic()}
    selector = selectors.DefaultSelector()
    for proc in procs:
        selector.register(proc.stderr, selectors.EVENT_READ, proc)
    waiting = set(procs)
    deadline = time.monotonic() + 120
    while waiting and time.monotonic() < deadline:
        for key, _ in selector.select(timeout=1):
            line = key.fileobj.readline()
            if b'ready' in line or not line:
                waiting.discard(key.data)
                selector.unregister(key.fileobj)
    marks['ready'] = time.monotonic()
    for proc in procs:
        proc.send_signal(signal.SIGINT)
    try:
        codes = [proc.wait(timeout=60) for proc in procs]
    finally:  # a talker that hangs at shutdown must not outlive the benchmark
        for proc in procs:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    marks['shutdown'] = time.monotonic()
    for proc in procs:
        proc.stderr.close()
    if waiting or any(codes):
        raise RuntimeError(f'direct N={count}: {len(waiting)} never ready, exit codes {codes}')
    return {key: value - t0 for key, value in marks.items()}


def _cpu(who: int) -> float:
    usage = resource.getrusage(who)
    return usage.ru_utime + usage.ru_stime


def _ratio(ours: float, reference: float | None) -> str:
    return '-' if reference is None else f'{ours / reference:.2f}'


def _ref(value: float | None) -> str:
    return '-' if value is None else f'{value:.2f}'


def main() -> int:
    """Run the benchmark and print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--counts', type=int, nargs='+', default=[1, 10, 30])
    parser.add_argument('--repeat', type=int, default=3)
    opts = parser.parse_args()
    lease = lease_domain()  # the allocator of CONTRIBUTING.md; held until the table is done
    domain_id = lease.domain_id
    os.environ.update({'ROS_DOMAIN_ID': str(domain_id),
                       'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST',
                       'RCUTILS_COLORIZED_OUTPUT': '0'})
    with tempfile.TemporaryDirectory(prefix='bench-launch-') as tmp:
        os.environ['ROS_LOG_DIR'] = os.path.join(tmp, 'log')
        print(f'building the talker package (domain {domain_id}) ...', file=sys.stderr)
        prefix = build_talker_package(Path(tmp) / 'ws')
        use_prefix(prefix)
        talker = str(prefix / 'lib' / 'bench_pkg' / 'talker')
        results, floors = {}, {}
        for count in opts.counts:
            runs, direct = [], []
            for _ in range(opts.repeat):
                direct.append(run_direct(count, talker))
                saved = sys.stdout
                sys.stdout = open(os.devnull, 'w')  # noqa: SIM115 - launch chatter hidden
                try:
                    runs.append(run_once(count))
                finally:
                    sys.stdout.close()
                    sys.stdout = saved
            results[count] = {key: statistics.median(r[key] for r in runs) for key in runs[0]}
            floors[count] = {key: statistics.median(r[key] for r in direct) for key in direct[0]}
    lease.release()
    print(f'\nmedian of {opts.repeat} runs, seconds from the start of the launch; '
          'floor: the same talkers without launch, this run; Jazzy: real launch, 2 cores')
    header = (f"{'N':>4} | {'started':>8} {'Jazzy':>6} {'ratio':>6} | {'ready':>6} {'floor':>6} | "
              f"{'shutdown':>8} {'floor':>6} {'ratio':>6} {'Jazzy':>6} {'ratio':>6} | "
              f"{'launch cpu':>10} {'nodes cpu':>9}")
    print(header)
    print('-' * len(header))
    for count, timing in results.items():
        floor = floors[count]
        ref_started, ref_shutdown = REFERENCE.get(count, (None, None))
        print(f"{count:>4} | {timing['started']:>8.3f} {_ref(ref_started):>6} "
              f"{_ratio(timing['started'], ref_started):>6} | "
              f"{timing['ready']:>6.2f} {floor['ready']:>6.2f} | "
              f"{timing['shutdown']:>8.2f} {floor['shutdown']:>6.2f} "
              f"{_ratio(timing['shutdown'], floor['shutdown']):>6} "
              f"{_ref(ref_shutdown):>6} {_ratio(timing['shutdown'], ref_shutdown):>6} | "
              f"{timing['launch_cpu']:>10.2f} {timing['nodes_cpu']:>9.2f}")
    return 0


if __name__ == '__main__':
    sys.exit(main())
