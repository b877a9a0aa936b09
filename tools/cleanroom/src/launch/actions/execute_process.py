"""Run a command as a process of the launch."""
from __future__ import annotations

import asyncio
import signal
import traceback
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import (
    TYPE_CHECKING,
)

from ..action import Action
from ..conditions.evaluate_condition_expression import evaluate_condition_expression
from ..descriptions import Executable
from ..event import Event
from ..event_handler import EventHandler, normalize_entities
from ..event_handlers.on_process_exit import OnProcessExit
from ..event_handlers.on_process_io import OnProcessIO
from ..event_handlers.on_shutdown import OnShutdown
from ..events import Shutdown, matches_action
from ..events.process import (
    ProcessExited,
    ProcessStarted,
    ProcessStderr,
    ProcessStdin,
    ProcessStdout,
    ProcessTargetedEvent,
    ShutdownProcess,
    SignalProcess,
)
from ..launch_description_entity import LaunchDescriptionEntity
from ..logging import get_logger
from ..substitution import Substitution
from ..substitutions.launch_configuration import LaunchConfiguration
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from ._process_output import ProcessOutput
from ._process_runner import RunningProcess
from .opaque_function import OpaqueFunction

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType

SubstitutionsList = list[Substitution]

# Overridable from the command line, e.g. `ros2 launch ... sigterm_timeout:=10`.
_DEFAULT_SIGTERM_TIMEOUT = LaunchConfiguration('sigterm_timeout', default=5)
_DEFAULT_SIGKILL_TIMEOUT = LaunchConfiguration('sigkill_timeout', default=5)


def _subs(value: object) -> SubstitutionsList:
    return normalize_to_list_of_substitutions(value)


def _perform(context: LaunchContext, subs: SubstitutionsList) -> str:
    return perform_substitutions(context, subs)


def _flag(context: LaunchContext, value: bool | SubstitutionsList) -> bool:
    return value if isinstance(value, bool) else evaluate_condition_expression(context, value)


def _targeted_handler(action: ExecuteProcess, event_type: type[ProcessTargetedEvent],
                      on_event: Callable[[LaunchContext], None]) -> EventHandler:
    """An EventHandler taking `event_type` events aimed at `action`, as Jazzy's are."""
    def matches(event: Event) -> bool:
        return isinstance(event, event_type) and bool(event.process_matcher(action))
    return EventHandler(matcher=matches, entities=OpaqueFunction(function=on_event))


class ExecuteProcess(Action):
    """Start a process when visited; report its start, output and exit as events.

    `cmd` is a list of arguments, each text or substitutions; it is kept as a
    mutable `list[list[Substitution]]` so that subclasses (launch_ros' Node)
    can append arguments in their own execute() before calling this one.
    The process is named `<name or basename of cmd[0]>-N`, N counting every
    process started by the LaunchService.  On shutdown it gets SIGINT, then
    SIGTERM after `sigterm_timeout` seconds, then SIGKILL after a further
    `sigkill_timeout` seconds.  With output 'screen' or 'both' each line the
    process writes is printed as `output_format.format(line=..., this=<this
    action>)`; the default `[{this.process_description.final_name}] {line}`
    gives `[talker-1] ...`.  The log files keep the bare line.
    """

    def __init__(
        self, *,
        cmd: Iterable[SomeSubstitutionsType],
        prefix: SomeSubstitutionsType | None = None,
        name: SomeSubstitutionsType | None = None,
        cwd: SomeSubstitutionsType | None = None,
        env: Mapping | Iterable[tuple] | None = None,
        additional_env: Mapping | Iterable[tuple] | None = None,
        shell: bool = False,
        sigterm_timeout: SomeSubstitutionsType = _DEFAULT_SIGTERM_TIMEOUT,
        sigkill_timeout: SomeSubstitutionsType = _DEFAULT_SIGKILL_TIMEOUT,
        emulate_tty: bool | SomeSubstitutionsType = False,
        output: SomeSubstitutionsType = 'log',
        output_format: str = '[{this.process_description.final_name}] {line}',
        cached_output: bool = False,
        log_cmd: bool = False,
        on_exit: object = None,
        respawn: bool | SomeSubstitutionsType = False,
        respawn_delay: float | None = None,
        respawn_max_retries: int = -1,
        **kwargs: object,
    ) -> None:
        super().__init__(**kwargs)
        self.__description = Executable(cmd=cmd, prefix=prefix, name=name, cwd=cwd, env=env,
                                        additional_env=additional_env)
        self.__shell = shell
        self.__sigterm_timeout = _subs(str(sigterm_timeout)) \
            if isinstance(sigterm_timeout, (int, float)) else _subs(sigterm_timeout)
        self.__sigkill_timeout = _subs(str(sigkill_timeout)) \
            if isinstance(sigkill_timeout, (int, float)) else _subs(sigkill_timeout)
        self.__emulate_tty = emulate_tty if isinstance(emulate_tty, bool) else _subs(emulate_tty)
        self.__output = _subs(output)
        self.__output_format = output_format
        self.__cached_output = cached_output
        self.__log_cmd = log_cmd
        self.__on_exit = on_exit
        self.__respawn = respawn if isinstance(respawn, bool) else _subs(respawn)
        self.__respawn_delay = respawn_delay
        self.__respawn_max_retries = respawn_max_retries
        # state once executed
        self.__context: LaunchContext | None = None
        self.__process: RunningProcess | None = None
        self.__future: asyncio.Future | None = None
        self.__shutdown_requested = False
        self.__unhandled_output = 0  # output events emitted, not yet handled
        self.__exit_code: int | None = None  # an exit waiting for them
        self.__stop_requested: bool | None = None
        self.__timers: list[asyncio.TimerHandle] = []
        self.__respawn_handle: asyncio.TimerHandle | None = None
        self.__respawn_count = 0
        self.__output_handler: ProcessOutput | None = None
        self.__logger = None

    # --- public properties --------------------------------------------------
    @property
    def process_description(self) -> Executable:
        """The command as given and, once started, as expanded (`final_name`, ...)."""
        return self.__description

    @property
    def cmd(self) -> list[SubstitutionsList]:
        """The command; a mutable list of argument substitution lists."""
        return self.__description.cmd

    @property
    def name(self) -> object:
        """The final name (e.g. 'talker-1') once started, else the given name."""
        final_name = self.__final_name
        return final_name if final_name is not None else self.__description.name

    @property
    def prefix(self) -> SubstitutionsList | None:
        """The prefix command, as substitutions."""
        return self.__description.prefix

    @property
    def cwd(self) -> SubstitutionsList | None:
        """The working directory, as substitutions."""
        return self.__description.cwd

    @property
    def env(self) -> list[tuple[SubstitutionsList, SubstitutionsList]] | None:
        """The replacement environment, as substitution pairs."""
        return self.__description.env

    @property
    def additional_env(self) -> list[tuple[SubstitutionsList, SubstitutionsList]] | None:
        """Variables added to the environment, as substitution pairs."""
        return self.__description.additional_env

    @property
    def shell(self) -> bool:
        """True if the command runs through a shell."""
        return self.__shell

    @property
    def output(self) -> SubstitutionsList:
        """The output setting, as substitutions."""
        return self.__output

    @property
    def process_details(self) -> dict[str, object] | None:
        """name, cmd, cwd, env and pid of the started process (None before start)."""
        description = self.__description
        if description.final_name is None:
            return None
        return {'name': description.final_name, 'cmd': description.final_cmd,
                'cwd': description.final_cwd, 'env': description.final_env,
                'pid': self.__process.pid if self.__process is not None else None}

    @property
    def return_code(self) -> int | None:
        """The exit code of the last run, if it has exited."""
        return self.__process.returncode if self.__process is not None else None

    def get_stdout(self) -> str:
        """Cached stdout (requires cached_output=True)."""
        if not self.__cached_output:
            raise RuntimeError('cached output must be true to be able to get stdout, '
                               f"proc '{self.__final_name}'")
        return self.__output_handler.cached(1) if self.__output_handler is not None else ''

    def get_stderr(self) -> str:
        """Cached stderr (requires cached_output=True)."""
        if not self.__cached_output:
            raise RuntimeError('cached output must be true to be able to get stderr, '
                               f"proc '{self.__final_name}'")
        return self.__output_handler.cached(2) if self.__output_handler is not None else ''

    def describe(self) -> str:
        """`ExecuteProcess(cmd=[...], cwd=None, env=None, shell=False)`, as `ros2 launch -p`."""
        def join(subs: SubstitutionsList) -> str:
            return ' + '.join(s.describe() for s in subs)
        cmd = ', '.join(join(c) for c in self._described_cmd())
        cwd = None if self.cwd is None else f"'{join(self.cwd)}'"  # quoted again, as Jazzy
        env = None if self.env is None else \
            '{' + ', '.join(f'{join(k)}: {join(v)}' for k, v in self.env) + '}'
        return f'ExecuteProcess(cmd=[{cmd}], cwd={cwd}, env={env}, shell={self.__shell})'

    def _described_cmd(self) -> list[SubstitutionsList]:
        """The command as described before execution (Node adds its name arguments)."""
        return self.cmd

    def describe_conditional_sub_entities(
            self) -> list[tuple[str, Sequence[LaunchDescriptionEntity]]]:
        """The on_exit entities, if any."""
        if self.__on_exit is None or callable(self.__on_exit):
            return []
        return [('on exit', normalize_entities(self.__on_exit))]

    def get_asyncio_future(self) -> asyncio.Future | None:
        """Done when the process has exited for good (no respawn pending)."""
        return self.__future

    @property
    def __final_name(self) -> str | None:
        return self.__description.final_name

    # --- execution ------------------------------------------------------------
    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Expand the command and start the process."""
        if context.is_shutdown:
            return None
        self.__expand(context)
        self.__context = context
        self.__logger = get_logger(self.__final_name)
        # The same handlers as Jazzy's (`ros2 launch -d` lists each one that takes an
        # event); they stay registered after the process exits, as in Jazzy.
        for handler in (
                _targeted_handler(self, ShutdownProcess, self.__on_shutdown_process),
                _targeted_handler(self, SignalProcess, self.__on_signal_process),
                OnProcessIO(target_action=self, on_stdin=self.__on_process_stdin_event,
                            on_stdout=self.__on_output_event, on_stderr=self.__on_output_event),
                OnProcessExit(target_action=self, on_exit=self.__on_exit),
                OnProcessExit(target_action=self, on_exit=self.__respawn_or_complete),
                OnShutdown(on_shutdown=self.__on_shutdown)):
            context.register_event_handler(handler)
        loop = context.asyncio_loop
        assert loop is not None, 'ExecuteProcess needs a running LaunchService'
        self.__future = loop.create_future()
        self.__start(context)
        return None

    def __expand(self, context: LaunchContext) -> None:
        self.__description._expand(context)
        self.__output_handler = ProcessOutput(
            self.__final_name, _perform(context, self.__output),
            self.__cached_output, screen_line=self.__screen_line)

    def __screen_line(self, line: str) -> str:
        """A line of output as the screen shows it: `output_format` with `line` and `this`."""
        return self.__output_format.format(line=line, this=self)

    def __start(self, context: LaunchContext) -> None:
        assert self.__description.final_cmd is not None and self.__description.final_env is not None
        emulate_tty = self.__emulate_tty
        if 'emulate_tty' in context.launch_configurations:
            emulate_tty = _subs(str(context.launch_configurations['emulate_tty']))
        if self.__log_cmd:
            self.__logger.info(f"process details: cmd='{' '.join(self.__description.final_cmd)}', "
                               f"cwd='{self.__description.final_cwd}', "
                               f'custom_env?={self.env is not None}')
        self.__process = None  # until spawned; a shutdown meanwhile is applied afterwards
        process = RunningProcess(
            context.asyncio_loop, self.__description.final_cmd, cwd=self.__description.final_cwd,
            env=self.__description.final_env, shell=self.__shell,
            emulate_tty=_flag(context, emulate_tty),
            on_output=self.__on_output, on_exit=self.__on_process_exit)
        spawning = context._run_in_spawner(process.spawn)
        spawning.add_done_callback(lambda done: self.__on_spawned(context, process, done))

    def __on_spawned(self, context: LaunchContext, process: RunningProcess,
                     spawning: asyncio.Future) -> None:
        error = spawning.exception()
        if error is not None:
            self.__logger.error('exception occurred while executing process:\n'
                                + ''.join(traceback.format_exception(error)))
            self.__complete()
            return
        self.__process = process
        process.attach()
        self.__logger.info(f'process started with pid [{process.pid}]')
        context._emit_event(ProcessStarted(**self.__event_fields()))
        if self.__stop_requested is not None:  # shutdown came while the process was starting
            self.__stop(context, self.__stop_requested)

    def __event_fields(self) -> dict[str, object]:
        description = self.__description
        return {'action': self, 'name': description.final_name, 'cmd': description.final_cmd,
                'cwd': description.final_cwd, 'env': description.final_env,
                'pid': self.__process.pid if self.__process is not None else 0}

    # --- output ---------------------------------------------------------------
    def __on_output(self, fd: int, data: bytes) -> None:
        """Emit what the process wrote; it is printed and logged when the event is handled."""
        assert self.__context is not None
        event_type = ProcessStdout if fd == 1 else ProcessStderr
        self.__unhandled_output += 1
        self.__context.emit_event_sync(event_type(text=data, **self.__event_fields()))

    def __on_output_event(self, event: ProcessStdout | ProcessStderr) -> None:
        assert self.__output_handler is not None
        self.__output_handler.write(event.fd, event.text)
        self.__unhandled_output -= 1
        if self.__unhandled_output == 0 and self.__exit_code is not None:
            self.__on_process_exit(self.__exit_code)

    # --- exit, respawn, shutdown ------------------------------------------------
    def __on_process_exit(self, returncode: int) -> None:
        """Log the exit once the lines the process wrote are printed (as Jazzy mostly shows it)."""
        context = self.__context
        assert context is not None and self.__process is not None
        if self.__unhandled_output:
            self.__exit_code = returncode  # done by the last output event's handler
            return
        self.__exit_code = None
        for timer in self.__timers:
            timer.cancel()
        self.__timers.clear()
        pid = self.__process.pid
        if returncode == 0:
            self.__logger.info(f'process has finished cleanly [pid {pid}]')
        else:
            self.__logger.error(f'process has died [pid {pid}, exit code {returncode}, '
                                f"cmd '{' '.join(self.__description.final_cmd)}'].")
        context._emit_event(ProcessExited(returncode=returncode, **self.__event_fields()))

    def __respawn_or_complete(self, event: ProcessExited, context: LaunchContext) -> None:
        """Handling its exit event: print an unfinished last line (after the exit line,
        as in Jazzy), then start the process again or be done."""
        self.__output_handler.flush()
        if self.__should_respawn(context):
            self.__respawn_count += 1
            delay = self.__respawn_delay or 0.0
            self.__respawn_handle = context.asyncio_loop.call_later(delay, self.__respawn_now)
        else:
            self.__complete()

    def __should_respawn(self, context: LaunchContext) -> bool:
        if context.is_shutdown or self.__shutdown_requested:
            return False
        if not _flag(context, self.__respawn):
            return False
        return self.__respawn_max_retries < 0 or \
            self.__respawn_count < self.__respawn_max_retries

    def __respawn_now(self) -> None:
        self.__respawn_handle = None
        if self.__context is None or self.__context.is_shutdown or self.__shutdown_requested:
            self.__complete()
            return
        self.__start(self.__context)

    def __complete(self) -> None:
        if self.__future is not None and not self.__future.done():
            self.__future.set_result(None)

    def __on_shutdown(self, event: Shutdown, context: LaunchContext) -> None:
        self.__shutdown(context, not event.due_to_sigint or context.noninteractive)

    def __on_shutdown_process(self, context: LaunchContext) -> None:
        self.__shutdown(context, True)

    def __on_signal_process(self, context: LaunchContext) -> None:
        event: SignalProcess = context.locals.event
        if self.__process is None:
            return
        if not self.__process.running:
            # Jazzy's words ('not set'), seen with `ros2 launch -d` when the process was
            # stopped by the group's Ctrl-C before its SIGINT event was handled.
            self.__logger.debug(f"signal '{event.signal_name}' not set to "
                                f"'{self.__final_name}' because it is already closing")
            return
        self.__signal(event.signal)

    def __on_process_stdin_event(self, event: ProcessStdin) -> None:
        """Jazzy writes nothing to the process: it only warns, naming this handler."""
        assert self.__logger is not None
        self.__logger.warning(
            f"in ExecuteProcess('{id(self)}').__on_process_stdin_event()")

    def __shutdown(self, context: LaunchContext, send_sigint: bool) -> None:
        if self.__shutdown_requested:
            return
        self.__shutdown_requested = True
        if self.__respawn_handle is not None:
            self.__respawn_handle.cancel()
            self.__respawn_handle = None
            self.__complete()
            return
        if self.__process is None:  # still starting: stop it once it has started
            self.__stop_requested = send_sigint
            return
        self.__stop(context, send_sigint)

    def __stop(self, context: LaunchContext, send_sigint: bool) -> None:
        """SIGINT (unless the terminal sent it), then SIGTERM, then SIGKILL."""
        self.__stop_requested = None
        if self.__process is None or not self.__process.running:
            return
        if send_sigint:  # as in Jazzy, through a SignalProcess event (`ros2 launch -d` shows it)
            context.emit_event_sync(SignalProcess(signal_number=signal.SIGINT,
                                                  process_matcher=matches_action(self)))
        sigterm_timeout = _perform(context, self.__sigterm_timeout)
        sigkill_timeout = _perform(context, self.__sigkill_timeout)
        term_after = float(sigterm_timeout)
        kill_after = term_after + float(sigkill_timeout)
        loop = context.asyncio_loop

        def escalate_to_sigterm() -> None:
            if self.__process is not None and self.__process.running:
                self.__logger.error(
                    f"process[{self.__final_name}] failed to terminate '{sigterm_timeout}' "
                    "seconds after receiving 'SIGINT', escalating to 'SIGTERM'")
                self.__signal(signal.SIGTERM)

        def escalate_to_sigkill() -> None:
            if self.__process is not None and self.__process.running:
                self.__logger.error(
                    f"process[{self.__final_name}] failed to terminate '{kill_after}' "
                    "seconds after receiving 'SIGTERM', escalating to 'SIGKILL'")
                self.__signal(signal.SIGKILL)

        self.__timers = [loop.call_later(term_after, escalate_to_sigterm),
                         loop.call_later(kill_after, escalate_to_sigkill)]

    def __signal(self, signum: signal.Signals) -> None:
        assert self.__process is not None
        self.__logger.info(f"sending signal '{signum.name}' to process[{self.__final_name}]")
        self.__process.send_signal(signum)
