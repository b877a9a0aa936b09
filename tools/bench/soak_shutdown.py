"""Soak test of node shutdown: start and stop the book's nodes many times and count hangs.

    .venv/bin/python tools/bench/soak_shutdown.py [--cycles 300] [--variant default] \
        [--variant udp] [--variant double-sigint] [--variant kill-peer] [--load 2] \
        [--nodes robot|capstone|both] [--copies 1] [--robots 2] [--hold-max 1] \
        [--gdb] [--patience 0] [--env KEY=VALUE] [--budget MINUTES]

    # what found the cause: 6 nodes, one busy CPU, 50 cycles of each variant
    .venv/bin/python tools/bench/soak_shutdown.py --cycles 50 --copies 2 --load 1 --gdb

Why it exists: in CI a node of the book sometimes hangs at shutdown.  It
ignores SIGINT, then SIGTERM ("failed to terminate '5' seconds after
receiving 'SIGINT'" ... "escalating to 'SIGKILL'") and is SIGKILLed; most
often robot_controller of my_robot_pkg, and the capstone's nodes when about
sixteen stop at once.  The tests carried a rerun for it (DDS_SHUTDOWN_HANG in
tests/snippets/_launch_log.py) until tools/ddsfix fixed the cause (below).
This script reproduces the stop outside pytest and launch, many times, under
CPU load, and counts the hangs for each suspected cause.

Each cycle starts the nodes concurrently, as `ros2 run` would (the built
executables of the book's workspace, build/ws/install, sourced), waits until
each has printed its first log line, leaves them running a random moment
(--hold), then signals them all at once, as `ros2 launch` does.  A node
still alive --hang-after seconds (5, launch's SIGINT timeout) after its
SIGINT is a hang: the script records its threads (name, state, kernel wait
channel), the main thread's kernel stack, its signal masks and last output
lines (and, with --gdb, the main thread's system calls over 1 s, every
thread's native backtrace and which thread owns each mutex a thread waits
for), waits --patience seconds more for it to end by itself, then sends
SIGTERM and, 2 s later, SIGKILL.  Variants, each reported separately:

    default        SIGINT to every node
    udp            the same with FASTDDS_BUILTIN_TRANSPORTS=UDPv4 (no shared memory)
    double-sigint  a second SIGINT 50 ms after the first (a terminal's group signal
                   and launch's forwarded one both reaching the nodes)
    kill-peer      SIGKILL to one node (in turn), leaving its shared memory behind,
                   then SIGINT to the rest

The run has its own ROS_DOMAIN_ID (a domain_coordinator lease, as the tests
have) and ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST.  Every process it starts
gets its own process group and PR_SET_PDEATHSIG, and every group is killed at
exit, also on Ctrl-C, SIGTERM or an error.  Fast DDS's files in /dev/shm are
counted before and after each variant (those no live process maps are
orphans).  Details of each hang and a JSON record of the run go to --out
(default build/bench/soak_shutdown/<time>/).  It is a benchmark, not a test:
it prints a table and exits 0.

What it found (Fast DDS 2.14.5 and rmw_fastrtps 8.4.3 from PyPI, Nov 2026):
about one cycle in fifty hangs, in every variant but udp (whose 0 of 50 was
not enough cycles to tell).  The hung node's main thread spins (state R, no
system call at all) in DomainParticipant::set_listener(nullptr), which
rmw_fastrtps's destroy_participant calls when the last node of the context
is destroyed.  A discovery receive thread, inside onReaderDiscovery (a peer's
endpoint going away), waits for a mutex that the main thread holds, and the
main thread waits for that callback to finish.  set_listener's default
timeout is infinite, a steady_clock time_point::max() deadline.  The wheel's
libstdc++ (built on glibc 2.28, so without pthread_cond_clockwait) converts
that deadline to a system_clock one, which overflows to a negative timespec.
glibc's pthread_cond_timedwait then fails at once with EINVAL, without
releasing the mutex.  So the loop never lets the callback thread finish, and
the hang does not end (still there 25 s after the SIGINT).  A stale
/dev/shm (kill-peer) and a second SIGINT do not make hangs more frequent; a
second SIGINT makes nodes exit -2 (KeyboardInterrupt in main's finally).

The fix (Nov 2026): tools/ddsfix/forever_wait.c, an LD_PRELOAD shim that
tools/setup_env.sh builds into a venv of the wheels and textbook.isolation
preloads into every ROS run (so also into this script's nodes; `--env
LD_PRELOAD=` runs them without it).  A deadline with tv_sec < 0 or tv_nsec
outside [0, 1e9) comes only from such an overflow, and the shim waits without
a deadline then, as the caller meant (what Jazzy's own Fast DDS, built with
pthread_cond_clockwait, does).  Confirmed: libfastrtps's
DomainParticipant::set_listener calls steady_clock::now, system_clock::now,
then pthread_cond_timedwait (objdump), and the same libstdc++ code compiled
without pthread_cond_clockwait hands glibc {-7427607324 s, -568803076 ns} and
spins for ever, and waits and wakes under the shim (tests/tools/test_ddsfix.py).
Measured with the shim: 0 hangs in 200 cycles of 6 nodes (--copies 2 --load 1,
1200 stops) and in 100 of 16 (--nodes both --copies 2 --load 1, 1600 stops).
That day the hang did not show without it either: 0 in 100 cycles of 6 nodes
and in 180 of 16 (2880 stops, --hold-max 1 and 0.05), so the soak alone does
not tell the two apart; the mechanism does.
"""
from __future__ import annotations

import argparse
import collections
import functools
import json
import os
import random
import signal
import statistics
import subprocess
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO

from rclhelpers.processes import die_with_parent
from textbook import environment, isolation, workspace

ROOT = Path(__file__).resolve().parents[2]
VARIANTS = ('default', 'udp', 'double-sigint', 'kill-peer')
SHM = Path('/dev/shm')
MY_ROBOT_NODES = ('robot_controller', 'sensor_publisher', 'data_processor')
# The capstone's nodes that log a line when they are up (mission_recorder, a
# lifecycle node, logs nothing before it is configured).
CAPSTONE_NODES = ('wall_sensor', 'pose_estimator', 'patrol_planner', 'controller',
                  'safety_monitor')
TERM_GRACE = 2.0  # seconds between the SIGTERM to a hung node and its SIGKILL


@dataclass(frozen=True)
class NodeSpec:
    """One node to start each cycle: the installed executable and its arguments."""

    label: str
    package: str
    executable: str
    args: tuple[str, ...] = ()

    def command(self, install: Path) -> list[str]:
        """The command line `ros2 run` would execute."""
        return [str(install / self.package / 'lib' / self.package / self.executable),
                *self.args]


@dataclass
class Running:
    """A started node: its process, its output and when it stopped."""

    spec: NodeSpec
    proc: subprocess.Popen
    lines: collections.deque = field(default_factory=lambda: collections.deque(maxlen=30))
    up: threading.Event = field(default_factory=threading.Event)
    signalled_at: float | None = None
    exited_at: float | None = None


@dataclass
class VariantResult:
    """What the cycles of one variant measured."""

    variant: str
    cycles: int = 0
    stops: int = 0  # nodes stopped with SIGINT
    hangs: int = 0
    cycles_with_hang: int = 0
    hung_nodes: collections.Counter = field(default_factory=collections.Counter)
    term_helped: int = 0  # hung nodes that SIGTERM ended before SIGKILL
    unclean: int = 0  # SIGINTed nodes that exited with a code other than 0
    unclean_codes: collections.Counter = field(default_factory=collections.Counter)
    start_failures: int = 0  # nodes that printed nothing in --startup-timeout or exited early
    stop_times: list[float] = field(default_factory=list)
    node_stop_times: dict = field(default_factory=lambda: collections.defaultdict(list))
    wall: float = 0.0
    shm_before: dict = field(default_factory=dict)
    shm_after: dict = field(default_factory=dict)
    hang_files: list[str] = field(default_factory=list)

    def row(self) -> list[str]:
        """The variant's line of the summary table."""
        times = sorted(self.stop_times)
        p95 = times[min(len(times) - 1, int(0.95 * len(times)))] if times else float('nan')
        return [
            self.variant, str(self.cycles), str(self.stops), str(self.hangs),
            _percent(self.cycles_with_hang, self.cycles), _percent(self.hangs, self.stops),
            str(self.unclean), str(self.start_failures),
            f'{statistics.median(times):.2f}' if times else '-',
            f'{p95:.2f}' if times else '-', f'{times[-1]:.2f}' if times else '-',
            f'{self.wall / 60:.1f}',
        ]


HEADER = ['variant', 'cycles', 'stops', 'hangs', 'cycles w/ hang', 'per stop', 'unclean',
          'no start', 'median s', 'p95 s', 'max s', 'min']


def _percent(part: int, whole: int) -> str:
    return f'{100.0 * part / whole:.2f}%' if whole else '-'


def node_specs(install: Path, nodes: str, copies: int, robots: int) -> list[NodeSpec]:
    """The nodes each cycle starts: my_robot_pkg's three (``copies`` times, each copy in a
    namespace of its own when there are several) and/or the capstone's per ``robots``."""
    specs: list[NodeSpec] = []
    if nodes in ('robot', 'both'):
        for copy in range(copies):
            args = ('--ros-args', '-r', f'__ns:=/copy{copy + 1}') if copies > 1 else ()
            specs += [NodeSpec(f'{name}' + (f'@copy{copy + 1}' if copies > 1 else ''),
                               'my_robot_pkg', name, args) for name in MY_ROBOT_NODES]
    if nodes in ('capstone', 'both'):
        defaults = (install / 'capstone_bringup' / 'share' / 'capstone_bringup'
                    / 'config' / 'defaults.yaml')
        for number in range(1, robots + 1):
            args = ('--ros-args', '-r', f'__ns:=/turtle{number}', '--params-file', str(defaults))
            specs += [NodeSpec(f'{name}@turtle{number}', 'capstone_robot', name, args)
                      for name in CAPSTONE_NODES]
    return specs


def shm_state() -> dict:
    """Fast DDS's files in /dev/shm: how many, how many no live process maps (orphans),
    and the orphans' names."""
    files = sorted(p.name for p in SHM.iterdir() if 'fastrtps' in p.name or 'fastdds' in p.name)
    mapped: set[str] = set()
    for maps in Path('/proc').glob('[0-9]*/maps'):
        try:
            text = maps.read_text()
        except OSError:
            continue
        for line in text.splitlines():
            if '/dev/shm/' in line:
                mapped.add(line.rsplit('/dev/shm/', 1)[1].split(' ')[0])
    # A port's "_el" file is a lock held with flock, never mapped: orphan when its port is.
    def owner(name: str) -> str:
        return name[:-3] if name.endswith('_el') else name
    orphans = [name for name in files if owner(name) not in mapped]
    return {'files': len(files), 'orphans': len(orphans), 'orphan_names': orphans[:40]}


def _read(path: Path) -> str:
    try:
        return path.read_text(errors='replace')
    except OSError as error:
        return f'<{error.strerror}>'


def describe_process(pid: int) -> dict:
    """What /proc tells, cheaply, about a process that does not stop: its threads (name,
    state, kernel wait channel), the main thread's kernel stack and its signal masks."""
    threads = []
    for task in sorted(Path(f'/proc/{pid}/task').glob('*'), key=lambda p: int(p.name)):
        stat = _read(task / 'stat')
        state = stat.rsplit(')', 1)[1].split()[0] if ')' in stat else '?'
        threads.append({'tid': int(task.name), 'name': _read(task / 'comm').strip(),
                        'state': state, 'wchan': _read(task / 'wchan').strip()})
    status = _read(Path(f'/proc/{pid}/status'))
    signals = {line.split(':')[0]: line.split(':', 1)[1].strip() for line in status.splitlines()
               if line.startswith(('SigPnd', 'ShdPnd', 'SigBlk', 'SigIgn', 'SigCgt'))}
    return {'threads': threads, 'thread_count': len(threads),
            'main_stack': _read(Path(f'/proc/{pid}/stack')).strip(), 'signals': signals}


# gdb Python: for each thread blocked in pthread_mutex_lock, the LWP that owns that mutex
# (glibc's __data.__owner), which names the other side of a deadlock.
GDB_MUTEX_OWNERS = """
import gdb
for thread in gdb.selected_inferior().threads():
    thread.switch()
    frame = gdb.newest_frame()
    while frame is not None:
        if (frame.name() or '').lstrip('_') == 'pthread_mutex_lock':
            try:
                mutex = frame.read_var('mutex')
                owner = int(mutex.dereference()['__data']['__owner'])
                print('MUTEX LWP %d (%s) waits for mutex %#x owned by LWP %d'
                      % (thread.ptid[1], thread.name, int(mutex), owner))
            except Exception as error:
                print('MUTEX LWP %d: %s' % (thread.ptid[1], error))
            break
        frame = frame.older()
"""


def gdb_backtrace(pid: int, script: Path, timeout: float = 60.0) -> str:
    """Every thread's native backtrace and the owners of the mutexes threads wait for,
    from gdb in batch mode (``script``: GDB_MUTEX_OWNERS in a file)."""
    try:
        result = subprocess.run(['gdb', '-p', str(pid), '-batch', '-nx',
                                 '-ex', 'set pagination off', '-ex', 'thread apply all bt',
                                 '-x', str(script)],
                                capture_output=True, text=True, timeout=timeout)
    except (FileNotFoundError, subprocess.TimeoutExpired) as error:
        return f'<gdb: {error}>'
    return result.stdout + result.stderr


def syscall_counts(tid: int, seconds: float = 1.0) -> str:
    """strace -c of one thread for ``seconds``: which system calls a spinning thread makes
    (none at all: it spins in user space, never releasing a mutex another thread waits for)."""
    try:
        result = subprocess.run(['timeout', '-s', 'INT', str(seconds), 'strace', '-c', '-p',
                                 str(tid)], capture_output=True, text=True, timeout=seconds + 10)
    except (FileNotFoundError, subprocess.TimeoutExpired) as error:
        return f'<strace: {error}>'
    return result.stderr.strip()


def gdb_summary(backtrace: str) -> list[str]:
    """One line per thread: its name and the first Fast DDS / rcl / rmw frames."""
    summary = []
    for block in backtrace.split('\nThread ')[1:]:
        head, _, frames = block.partition('\n')
        name = head.split('"')[1] if '"' in head else head[:30]
        calls = []
        for frame in frames.splitlines():
            if ' in ' not in frame:
                continue
            call = frame.split(' in ', 1)[1].split(' (', 1)[0]
            if any(word in call for word in ('eprosima', 'rmw', 'rcl', 'Py', 'pthread', 'sem')):
                calls.append(call.replace('eprosima::fastdds::', '').replace(
                    'eprosima::fastrtps::', '')[:90])
            if len(calls) == 4:
                break
        summary.append(f'{name}: {" <- ".join(calls)}')
    return summary


class Soak:
    """Starts, stops and reaps the nodes; owns every process it started."""

    def __init__(self, options: argparse.Namespace, env: dict[str, str], out: Path,
                 install: Path) -> None:
        self.options = options
        self.env = env
        self.out = out
        self.install = install
        self.specs = node_specs(install, options.nodes, options.copies, options.robots)
        self.owned: list[subprocess.Popen] = []
        self.results: list[VariantResult] = []
        self.rng = random.Random(options.seed)

    # -- processes ---------------------------------------------------------------------
    def spawn(self, command: list[str], env: dict[str, str],
              output: int | None = subprocess.PIPE) -> subprocess.Popen:
        """Start ``command`` in a process group of its own that dies with this script."""
        proc = subprocess.Popen(
            command, env=env, stdin=subprocess.DEVNULL, stdout=output,
            stderr=subprocess.STDOUT if output == subprocess.PIPE else output,
            start_new_session=True,
            preexec_fn=functools.partial(die_with_parent, os.getpid(), signal.SIGKILL))
        self.owned.append(proc)
        return proc

    def kill_all(self) -> None:
        """SIGKILL every process group this script started and reap them."""
        for proc in self.owned:
            if proc.poll() is None:
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
        for proc in self.owned:
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                print(f'warning: pid {proc.pid} survived SIGKILL', file=sys.stderr)
        self.owned = [proc for proc in self.owned if proc.poll() is None]

    def start_load(self, count: int) -> list[subprocess.Popen]:
        """``count`` processes that keep a CPU busy."""
        return [self.spawn([sys.executable, '-c', 'while True: pass'], self.env,
                           output=subprocess.DEVNULL) for _ in range(count)]

    @staticmethod
    def _drain(stream: IO[bytes], node: Running) -> None:
        for raw in iter(stream.readline, b''):
            node.lines.append(raw.decode(errors='replace').rstrip())
            node.up.set()
        stream.close()

    # -- one cycle -----------------------------------------------------------------------
    def cycle(self, variant: str, number: int, result: VariantResult) -> None:
        """Start every node, wait until each is up, stop them as ``variant`` says."""
        env = dict(self.env)
        if variant == 'udp':
            env['FASTDDS_BUILTIN_TRANSPORTS'] = 'UDPv4'
        nodes = []
        for spec in self.specs:
            proc = self.spawn(spec.command(self.install), env)
            node = Running(spec, proc)
            threading.Thread(target=self._drain, args=(proc.stdout, node), daemon=True).start()
            nodes.append(node)
        deadline = time.monotonic() + self.options.startup_timeout
        for node in nodes:
            up = node.up.wait(max(0.0, deadline - time.monotonic()))
            if not up or node.proc.poll() is not None:
                result.start_failures += 1
                print(f'  [{variant} {number}] {node.spec.label} not up '
                      f'(exit {node.proc.poll()}): {list(node.lines)[-3:]}', flush=True)
        time.sleep(self.rng.uniform(self.options.hold_min, self.options.hold_max))

        targets = [node for node in nodes if node.proc.poll() is None]
        if variant == 'kill-peer' and targets:
            victim = nodes[number % len(nodes)]
            if victim.proc.poll() is None:
                victim.proc.send_signal(signal.SIGKILL)
                victim.proc.wait()
            targets = [node for node in targets if node is not victim]
            time.sleep(self.options.kill_delay)
        self._interrupt(targets)
        if variant == 'double-sigint':
            time.sleep(0.05)
            self._interrupt([node for node in targets if node.proc.poll() is None])
        hung = self._wait_exits(targets)
        for node in targets:
            if node in hung:
                continue
            result.stop_times.append(node.exited_at - node.signalled_at)
            result.node_stop_times[node.spec.label].append(node.exited_at - node.signalled_at)
            if node.proc.returncode != 0:
                result.unclean += 1
                result.unclean_codes[node.proc.returncode] += 1
                print(f'  [{variant} {number}] {node.spec.label} exit {node.proc.returncode}: '
                      f'{list(node.lines)[-2:]}', flush=True)
        for node in hung:
            self._handle_hang(variant, number, node, result)
        result.stops += len(targets)
        result.hangs += len(hung)
        result.cycles_with_hang += bool(hung)
        result.cycles += 1
        for node in nodes:  # the victim of kill-peer, and anything still there
            if node.proc.poll() is None:
                try:
                    os.killpg(node.proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            node.proc.wait()
        self.owned = [proc for proc in self.owned if proc.poll() is None]

    @staticmethod
    def _interrupt(targets: list[Running]) -> None:
        now = time.monotonic()
        for node in targets:
            if node.signalled_at is None:
                node.signalled_at = now
            try:
                node.proc.send_signal(signal.SIGINT)
            except ProcessLookupError:
                pass

    def _wait_exits(self, targets: list[Running]) -> list[Running]:
        """Wait until every target has exited or --hang-after has passed; the ones left."""
        left = list(targets)
        while left:
            now = time.monotonic()
            for node in list(left):
                if node.proc.poll() is not None:
                    node.exited_at = now
                    left.remove(node)
            if not left or now - min(n.signalled_at for n in left) > self.options.hang_after:
                break
            time.sleep(0.02)
        return left

    def _handle_hang(self, variant: str, number: int, node: Running,
                     result: VariantResult) -> None:
        pid = node.proc.pid
        record = {'variant': variant, 'cycle': number, 'node': node.spec.label, 'pid': pid,
                  'seconds_since_sigint': time.monotonic() - node.signalled_at,
                  **describe_process(pid), 'last_output': list(node.lines)}
        if self.options.gdb:
            record['main_thread_syscalls'] = syscall_counts(pid)
            script = self.out / 'gdb_mutex_owners.py'
            script.write_text(GDB_MUTEX_OWNERS)
            record['gdb'] = gdb_backtrace(pid, script)
            record['gdb_summary'] = gdb_summary(record['gdb'])
            record['mutex_owners'] = [line for line in record['gdb'].splitlines()
                                      if line.startswith('MUTEX')]
        if self.options.patience:
            try:
                node.proc.wait(self.options.patience)
                record['recovered_after'] = time.monotonic() - node.signalled_at
            except subprocess.TimeoutExpired:
                record['recovered_after'] = None
        node.proc.send_signal(signal.SIGTERM)
        try:
            node.proc.wait(TERM_GRACE)
            record['after_sigterm'] = f'exited {node.proc.returncode}'
            result.term_helped += 1
        except subprocess.TimeoutExpired:
            record['after_sigterm'] = 'still alive: SIGKILL'
            os.killpg(pid, signal.SIGKILL)
            node.proc.wait()
        result.hung_nodes[node.spec.label] += 1
        path = self.out / f'hang-{variant}-{number:04d}-{node.spec.label}.json'
        path.write_text(json.dumps(record, indent=1))
        result.hang_files.append(str(path))
        waits = collections.Counter(f'{t["name"]}:{t["wchan"]}' for t in record['threads'])
        print(f'  HANG [{variant} {number}] {node.spec.label} pid {pid}: '
              f'{record["thread_count"]} threads, main thread wchan '
              f'{record["threads"][0]["wchan"] if record["threads"] else "?"}, '
              f'{record["after_sigterm"]}; {dict(waits)}', flush=True)
        for line in record.get('gdb_summary', []):
            if 'eprosima' in line or 'rmw' in line or 'rcl' in line:
                print(f'      {line}', flush=True)
        for line in record.get('mutex_owners', []):
            print(f'      {line}', flush=True)
        if 'main_thread_syscalls' in record:
            calls = record['main_thread_syscalls'].splitlines()
            print(f'      main thread, 1 s of strace -c: {" | ".join(calls[-3:])}', flush=True)
        if self.options.patience:
            print(f'      exited by itself within --patience: '
                  f'{record["recovered_after"] is not None} ({record["recovered_after"]})',
                  flush=True)
        print(f'      details: {path}', flush=True)

    # -- a variant -----------------------------------------------------------------------
    def run_variant(self, variant: str) -> VariantResult:
        """--cycles cycles of ``variant``."""
        result = VariantResult(variant, shm_before=shm_state())
        self.results.append(result)  # also when interrupted: the cycles run so far count
        started = time.monotonic()
        print(f'{variant}: {self.options.cycles} cycles of {len(self.specs)} nodes; '
              f'/dev/shm {result.shm_before["files"]} Fast DDS files, '
              f'{result.shm_before["orphans"]} orphans', flush=True)
        try:
            self._cycles(variant, result, started)
        finally:
            result.wall = time.monotonic() - started
            result.shm_after = shm_state()
        return result

    def _cycles(self, variant: str, result: VariantResult, started: float) -> None:
        for number in range(self.options.cycles):
            if self.options.budget and time.monotonic() - started > self.options.budget * 60:
                print(f'  {variant}: budget of {self.options.budget} min reached', flush=True)
                break
            self.cycle(variant, number, result)
            if (number + 1) % self.options.progress == 0:
                times = result.stop_times
                print(f'  {variant}: {number + 1} cycles, {result.hangs} hangs, '
                      f'median stop {statistics.median(times) if times else 0:.2f} s, '
                      f'{(time.monotonic() - started) / (number + 1):.1f} s/cycle', flush=True)


def print_summary(results: list[VariantResult], options: argparse.Namespace,
                  domain: int) -> None:
    """The table, hangs by node and /dev/shm before/after, per variant."""
    rows = [HEADER, *(result.row() for result in results)]
    widths = [max(len(row[i]) for row in rows) for i in range(len(HEADER))]
    print(f'\nSummary (domain {domain}, load {options.load}, nodes {options.nodes}, '
          f'hold {options.hold_min}-{options.hold_max} s, hang = alive '
          f'{options.hang_after} s after SIGINT)')
    for index, row in enumerate(rows):
        print('  '.join(cell.rjust(width) for cell, width in zip(row, widths, strict=True)))
        if index == 0:
            print('  '.join('-' * width for width in widths))
    for result in results:
        extra = []
        if result.hung_nodes:
            extra.append(f'hung: {dict(result.hung_nodes)}, SIGTERM ended '
                         f'{result.term_helped} of {result.hangs}')
        if result.unclean_codes:
            extra.append(f'exit codes: {dict(result.unclean_codes)}')
        medians = {label: round(statistics.median(times), 2)
                   for label, times in sorted(result.node_stop_times.items())}
        extra.append(f'median stop by node: {medians}')
        before, after = result.shm_before, result.shm_after
        extra.append(f'/dev/shm Fast DDS files {before["files"]} -> {after["files"]}, '
                     f'orphans {before["orphans"]} -> {after["orphans"]}')
        print(f'{result.variant}: ' + '; '.join(extra))


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    """The command line."""
    parser = argparse.ArgumentParser(
        description='Start and stop nodes many times and count shutdown hangs.')
    parser.add_argument('--cycles', type=int, default=300, help='cycles per variant (300)')
    parser.add_argument('--variant', action='append', choices=VARIANTS,
                        help='a variant to run, repeatable, in order (default: all four)')
    parser.add_argument('--load', type=int, default=0, help='busy CPU processes meanwhile (0)')
    parser.add_argument('--nodes', choices=('robot', 'capstone', 'both'), default='robot',
                        help="my_robot_pkg's three nodes, the capstone's, or both (robot)")
    parser.add_argument('--copies', type=int, default=1,
                        help="copies of my_robot_pkg's nodes, each in a namespace (1)")
    parser.add_argument('--robots', type=int, default=2,
                        help='capstone robots: five nodes each, in /turtleN (2)')
    parser.add_argument('--hang-after', type=float, default=5.0,
                        help='seconds after SIGINT that make a node a hang (5)')
    parser.add_argument('--startup-timeout', type=float, default=30.0,
                        help='seconds to wait for the first log line of every node (30)')
    parser.add_argument('--hold-min', type=float, default=0.0,
                        help='least seconds the nodes run once up (0)')
    parser.add_argument('--hold-max', type=float, default=1.0,
                        help='most seconds the nodes run once up (1)')
    parser.add_argument('--kill-delay', type=float, default=0.2,
                        help='kill-peer: seconds between the SIGKILL and the SIGINTs (0.2)')
    parser.add_argument('--budget', type=float, default=0.0,
                        help='minutes per variant at most, 0 for no limit (0)')
    parser.add_argument('--gdb', action='store_true',
                        help="also record a hung node's main-thread system calls (strace -c, "
                             "1 s), gdb's backtrace of every thread and mutex owners")
    parser.add_argument('--patience', type=float, default=0.0,
                        help='seconds more to let a hung node end by itself before SIGTERM '
                             'and SIGKILL, to tell a slow stop from a deadlock (0)')
    parser.add_argument('--env', action='append', default=[], metavar='KEY=VALUE',
                        help='an extra environment variable for the nodes (a fix to try)')
    parser.add_argument('--seed', type=int, default=None, help='random seed of the hold times')
    parser.add_argument('--progress', type=int, default=25, help='a progress line every N cycles')
    parser.add_argument('--out', type=Path, default=None, help='folder for the hang records')
    return parser.parse_args(argv)


def _terminate(signum: int, _frame: object) -> None:
    raise SystemExit(128 + signum)


def main(argv: list[str] | None = None) -> int:
    """Run the variants, print the table; 0 (128 + the signal when SIGTERM or SIGHUP ended it)."""
    options = parse_args(argv)
    variants = options.variant or list(VARIANTS)
    # A handler of our own for each stop signal: the nodes start with the default
    # action for them even when this script was started with SIGINT ignored (`cmd &`),
    # and SIGTERM / SIGHUP still run the clean-up below.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, _terminate)
    signal.signal(signal.SIGHUP, _terminate)
    out = options.out or ROOT / 'build' / 'bench' / 'soak_shutdown' / time.strftime(
        '%Y%m%d-%H%M%S')
    out.mkdir(parents=True, exist_ok=True)
    install = workspace.ensure_built()
    with isolation.acquire_domain() as lease:
        base = {key: value for key, value in os.environ.items()
                if not key.startswith(('FASTDDS_', 'FASTRTPS_', 'RMW_'))}
        env = environment.ros_env(lease, base)
        for item in options.env:
            key, _, value = item.partition('=')
            env[key] = value
        soak = Soak(options, env, out, install)
        print(f'domain {lease.domain_id}; nodes: {", ".join(s.label for s in soak.specs)}; '
              f'records in {out}', flush=True)
        code = 0
        try:
            soak.start_load(options.load)
            for variant in variants:
                soak.run_variant(variant)
        except (KeyboardInterrupt, SystemExit) as stop:
            code = stop.code if isinstance(stop, SystemExit) else 0
            print('\ninterrupted: summary of the cycles run so far', flush=True)
        finally:
            soak.kill_all()
        results = [result for result in soak.results if result.cycles]
        print_summary(results, options, lease.domain_id)
        (out / 'summary.json').write_text(json.dumps({
            'argv': sys.argv, 'domain': lease.domain_id, 'extra_env': options.env,
            'results': [{**vars(r), 'hung_nodes': dict(r.hung_nodes),
                         'unclean_codes': dict(r.unclean_codes)} for r in results],
        }, indent=1))
    return code


if __name__ == '__main__':
    sys.exit(main())
