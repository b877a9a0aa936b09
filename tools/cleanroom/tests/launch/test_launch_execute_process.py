"""ExecuteProcess: names, command lines, output, respawn, log files."""
from __future__ import annotations

import inspect
import subprocess
import sys
from pathlib import Path

import launch.logging
import psutil
import pytest
from launch.actions import ExecuteProcess, GroupAction, SetLaunchConfiguration, TimerAction
from launch.substitutions import EnvironmentVariable, FindExecutable, LaunchConfiguration

PY = sys.executable


def test_names_count_every_process_of_the_launch(run_launch):
    result = run_launch([
        ExecuteProcess(cmd=['true']),
        ExecuteProcess(cmd=[FindExecutable(name='true')]),
        ExecuteProcess(cmd=['true'], name='custom'),
        ExecuteProcess(cmd=['true'], name=['dyn_', LaunchConfiguration('suffix')]),
    ], argv=('suffix:=x',))
    assert result.names == ['true-1', 'true-2', 'custom-3', 'dyn_x-4']


def test_processes_start_in_the_order_the_launch_reaches_them(run_launch):
    """As Jazzy: ProcessStarted events and "process started" lines come in the order
    of the description (launch_testing's proc_info lists the processes so)."""
    names = [f'p{index}' for index in range(8)]
    result = run_launch([ExecuteProcess(cmd=['sleep', '30'], name=name) for name in names],
                        shutdown_after=1.0)
    expected = [f'{name}-{number}' for number, name in enumerate(names, start=1)]
    assert result.names == expected
    started = [line.split('[')[2].split(']')[0] for line in result.output.splitlines()
               if 'process started with pid' in line]
    assert started == expected, result.output


def test_command_line_is_expanded_per_argument(run_launch, tmp_path):
    result = run_launch([
        SetLaunchConfiguration('word', 'two words'),
        ExecuteProcess(cmd=['echo', LaunchConfiguration('word'), ['a', 'b'],
                            EnvironmentVariable('CR_NOPE', default_value='dflt')],
                       cwd=str(tmp_path), name='echoer', output='screen'),
    ])
    (proc,) = result.processes
    assert proc['cmd'] == ['echo', 'two words', 'ab', 'dflt']
    assert proc['cwd'] == str(tmp_path)
    assert '[echoer-1] two words ab dflt' in result.output.splitlines()


def test_shell_and_prefix(run_launch):
    result = run_launch([
        ExecuteProcess(cmd=['echo', '$((1+2))'], shell=True, name='sh', output='screen'),
        ExecuteProcess(cmd=['hello'], prefix='echo prefixed', name='pre', output='screen'),
        GroupAction([
            SetLaunchConfiguration('launch-prefix', 'echo global'),
            SetLaunchConfiguration('launch-prefix-filter', '^match'),
            ExecuteProcess(cmd=['/bin/true'], name='skipped'),
            ExecuteProcess(cmd=['matchme'], name='matched', output='screen'),
        ]),
    ])
    lines = result.output.splitlines()
    assert '[sh-1] 3' in lines
    assert '[pre-2] prefixed hello' in lines
    assert '[matched-4] global matchme' in lines
    assert result.process('skipped-3')['cmd'] == ['/bin/true']


def test_output_modes_decide_what_reaches_the_screen(run_launch):
    script = 'import sys; print("OUT-LINE"); sys.stderr.write("ERR-LINE\\n")'
    result = run_launch([
        ExecuteProcess(cmd=[PY, '-c', script], name='screen', output='screen'),
        ExecuteProcess(cmd=[PY, '-c', script], name='log'),
        ExecuteProcess(cmd=[PY, '-c', script], name='own', output='own_log'),
    ])
    lines = result.output.splitlines()
    assert '[screen-1] OUT-LINE' in lines and '[screen-1] ERR-LINE' in lines
    assert '[log-2] ERR-LINE' in lines and '[log-2] OUT-LINE' not in lines
    assert not [line for line in lines if line.startswith('[own-3] ')]
    log_dir = Path(launch.logging.launch_config.log_dir)
    launch_log = (log_dir / 'launch.log').read_text()
    assert '[log-2]: OUT-LINE' in launch_log
    assert '[INFO] [screen-1]: process started with pid' in launch_log
    assert (log_dir / 'own-3-stdout.log').read_text() == 'OUT-LINE\n'
    assert (log_dir / 'own-3-stderr.log').read_text() == 'ERR-LINE\n'


def test_override_output_environment_variable(run_launch, monkeypatch):
    monkeypatch.setenv('OVERRIDE_LAUNCH_PROCESS_OUTPUT', 'both')
    result = run_launch([ExecuteProcess(cmd=['echo', 'hidden?'], name='quiet')])
    assert '[quiet-1] hidden?' in result.output.splitlines()


def test_output_format_shapes_every_screen_line(run_launch):
    script = 'import sys; print("first"); print("second"); sys.stderr.write("oops\\n")'
    result = run_launch([
        ExecuteProcess(cmd=[PY, '-c', script], name='fmt', output='both',
                       output_format='{this.process_description.final_name} says: {line}'),
        ExecuteProcess(cmd=['echo', 'bare'], name='plain', output='screen',
                       output_format='<{line}>'),
    ])
    lines = result.output.splitlines()
    for text in ('first', 'second', 'oops'):
        assert f'fmt-1 says: {text}' in lines
        assert f'[fmt-1] {text}' not in lines
    assert '<bare>' in lines and '[plain-2] bare' not in lines
    # the log file keeps the bare line under the process's name
    launch_log = (Path(launch.logging.launch_config.log_dir) / 'launch.log').read_text()
    assert '[fmt-1]: second' in launch_log and 'says:' not in launch_log


def test_process_description_is_the_expanded_command(run_launch, tmp_path):
    default = inspect.signature(ExecuteProcess).parameters['output_format'].default
    assert default == '[{this.process_description.final_name}] {line}'  # Jazzy's, documented
    proc = ExecuteProcess(cmd=['echo', LaunchConfiguration('word')], cwd=str(tmp_path),
                          name=['dyn_', LaunchConfiguration('word')],
                          additional_env={'CR_EXTRA': 'yes'}, output='screen')
    description = proc.process_description
    assert description.final_name is None and description.final_cmd is None
    result = run_launch([proc], argv=('word:=hi',))
    assert description.final_name == 'dyn_hi-1' == proc.name
    assert description.final_cmd == ['echo', 'hi'] == result.processes[0]['cmd']
    assert description.final_cwd == str(tmp_path)
    assert description.final_env['CR_EXTRA'] == 'yes'
    assert '[dyn_hi-1] hi' in result.output.splitlines()


def test_partial_last_line_and_emulate_tty(run_launch):
    result = run_launch([
        ExecuteProcess(cmd=['printf', 'no newline'], name='partial', output='screen'),
        ExecuteProcess(cmd=[PY, '-c', 'import sys; print(sys.stdout.isatty())'],
                       name='tty', output='screen', emulate_tty=True),
    ])
    lines = result.output.splitlines()
    assert '[partial-1] no newline' in lines
    assert '[tty-2] True' in lines


def test_cached_output(run_launch):
    proc = ExecuteProcess(cmd=['sh', '-c', 'echo out; echo err >&2'], cached_output=True)
    run_launch([proc])
    assert proc.get_stdout() == 'out\n'
    assert proc.get_stderr() == 'err\n'
    with pytest.raises(RuntimeError):
        ExecuteProcess(cmd=['true']).get_stdout()


def test_respawn_with_delay_and_retry_limit(run_launch):
    result = run_launch([
        ExecuteProcess(cmd=['sh', '-c', 'exit 2'], name='flaky', respawn=True,
                       respawn_delay=0.05, respawn_max_retries=2),
        ExecuteProcess(cmd=['true'], name='other'),
    ])
    assert result.names.count('flaky-1') == 3
    assert result.output.count('[ERROR] [flaky-1]: process has died') == 3


def test_respawn_stops_at_shutdown(run_launch):
    result = run_launch([
        ExecuteProcess(cmd=['sh', '-c', 'exit 1'], name='looping', respawn='true',
                       respawn_delay=0.1),
        TimerAction(period=0.35, actions=[ExecuteProcess(cmd=['true'], name='late')]),
    ], shutdown_after=0.5)
    assert 2 <= result.names.count('looping-1') <= 6
    assert 'late-2' in result.names
    assert result.returncode == 0


def test_missing_executable_is_reported_not_fatal(run_launch):
    result = run_launch([ExecuteProcess(cmd=['no-such-executable-cr'], name='ghost'),
                         ExecuteProcess(cmd=['true'], name='fine')])
    assert '[ERROR] [ghost-1]: exception occurred while executing process' in result.output
    assert result.names == ['fine-2']
    assert result.returncode == 0


def test_log_cmd(run_launch):
    result = run_launch([ExecuteProcess(cmd=['true', 'x'], log_cmd=True)])
    assert "[INFO] [true-1]: process details: cmd='true x'" in result.output


def test_children_get_the_death_signal():
    """PR_SET_PDEATHSIG: a child dies with the launch even if nobody stops it."""
    code = (
        'import asyncio, os\n'
        'from launch.actions._process_runner import RunningProcess\n'
        'loop = asyncio.new_event_loop()\n'
        "p = RunningProcess(loop, ['sleep', '30'], cwd=None, env=dict(os.environ), shell=False,"
        ' emulate_tty=False, on_output=lambda *a: None, on_exit=lambda c: None)\n'
        'p.start()\n'
        'print(p.pid, flush=True)\n'
        'import time; time.sleep(0.3)\n'
        'os._exit(0)  # no cleanup at all, as if the launch crashed\n')
    out = subprocess.run([PY, '-c', code], capture_output=True, text=True, timeout=30)
    child = psutil.Process(int(out.stdout.split()[0]))
    _gone, alive = psutil.wait_procs([child], timeout=5)
    assert not alive
