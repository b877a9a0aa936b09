"""Logging of the launch system: `[LEVEL] [name]: msg` on screen, and launch.log on disk.

Every launch gets a log folder `YYYY-MM-DD-HH-MM-SS-micro-host-pid` below the
ROS log directory (ROS_LOG_DIR, else ROS_HOME/log, else ~/.ros/log), created
lazily the first time something needs it.  Screen lines go to stdout, read
at write time so that redirected or captured stdout keeps working.
"""
from __future__ import annotations

import datetime
import logging
import os
import socket
import sys
import threading
from collections.abc import Callable
from typing import TextIO

__all__ = ['get_logger', 'get_output_loggers', 'launch_config', 'reset']

SCREEN_FORMAT = '[{levelname}] [{name}]: {msg}'
LOG_FORMAT = '{created:.7f} [{levelname}] [{name}]: {msg}'


def default_log_root() -> str:
    """The ROS log directory, as ROS 2 computes it."""
    if os.environ.get('ROS_LOG_DIR'):
        return os.path.expanduser(os.environ['ROS_LOG_DIR'])
    ros_home = os.environ.get('ROS_HOME') or os.path.join('~', '.ros')
    return os.path.join(os.path.expanduser(ros_home), 'log')


class _ScreenHandler(logging.Handler):
    """Writes to whatever sys.stdout is at the time of writing."""

    def emit(self, record: logging.LogRecord) -> None:
        try:
            stream: TextIO = sys.stdout
            stream.write(self.format(record) + '\n')
            stream.flush()
        except Exception:  # noqa: BLE001 - a closed stdout must not crash the launch
            self.handleError(record)


class _LaunchConfig:
    """Process-wide logging settings (level, log folder, handlers)."""

    def __init__(self) -> None:
        self._lock = threading.RLock()
        self.level = logging.INFO
        self._log_dir: str | None = None
        self._file_handler: logging.Handler | None = None
        self.screen_handler = _ScreenHandler()
        self.screen_handler.setFormatter(logging.Formatter(SCREEN_FORMAT, style='{'))
        self._configured: dict[str, logging.Logger] = {}
        self._own_logs: dict[str, TextIO] = {}

    @property
    def log_dir(self) -> str:
        """This launch's log folder, created on first use."""
        with self._lock:
            if self._log_dir is None:
                stamp = datetime.datetime.now().strftime('%Y-%m-%d-%H-%M-%S-%f')
                name = f'{stamp}-{socket.gethostname()}-{os.getpid()}'
                self._log_dir = os.path.join(default_log_root(), name)
            os.makedirs(self._log_dir, exist_ok=True)
            return self._log_dir

    @log_dir.setter
    def log_dir(self, value: str) -> None:
        with self._lock:
            self._close_files()
            self._log_dir = value

    def file_handler(self) -> logging.Handler:
        """The handler writing launch.log (opened on first record)."""
        with self._lock:
            if self._file_handler is None:
                handler = logging.FileHandler(os.path.join(self.log_dir, 'launch.log'),
                                              delay=True)
                handler.setFormatter(logging.Formatter(LOG_FORMAT, style='{'))
                self._file_handler = handler
                for logger in self._configured.values():
                    logger.addHandler(handler)
            return self._file_handler

    def set_level(self, level: int) -> None:
        """Set the level of every launch logger."""
        with self._lock:
            self.level = level
            for logger in self._configured.values():
                logger.setLevel(level)

    def own_log(self, filename: str) -> TextIO:
        """An open file in the log folder (for output='own_log')."""
        with self._lock:
            if filename not in self._own_logs:
                self._own_logs[filename] = open(  # noqa: SIM115 - closed by reset()
                    os.path.join(self.log_dir, filename), 'a', encoding='utf-8')
            return self._own_logs[filename]

    def _close_files(self) -> None:
        if self._file_handler is not None:
            for logger in self._configured.values():
                logger.removeHandler(self._file_handler)
            self._file_handler.close()
            self._file_handler = None
        for stream in self._own_logs.values():
            stream.close()
        self._own_logs.clear()

    def reset(self) -> None:
        """Forget the log folder and handlers (a new launch gets a new folder)."""
        with self._lock:
            self._close_files()
            self._log_dir = None
            self.level = logging.INFO
            for logger in self._configured.values():
                logger.setLevel(self.level)


launch_config = _LaunchConfig()


def get_logger(name: str | None = None) -> logging.Logger:
    """Return a logger printing `[LEVEL] [name]: msg` to the screen and launch.log."""
    name = name or 'launch'
    with launch_config._lock:
        logger = launch_config._configured.get(name)
        if logger is None:
            logger = logging.getLogger(name)
            logger.propagate = False
            logger.setLevel(launch_config.level)
            logger.addHandler(launch_config.screen_handler)
            launch_config._configured[name] = logger
        file_handler = launch_config.file_handler()  # (re)attaches itself after reset()
        if file_handler not in logger.handlers:
            logger.addHandler(file_handler)
        return logger


class _OutputLogger:
    """Writes process output lines to the screen and/or the log files."""

    def __init__(self, process_name: str, stream: str, to_screen: bool, to_log: bool,
                 own_log: bool, screen_line: Callable[[str], str] | None = None) -> None:
        self.process_name = process_name
        self.screen_line = screen_line or (lambda text: f'[{process_name}] {text}')
        self.stream = stream
        self.to_screen = to_screen
        self.to_log = to_log
        self.own_log = own_log

    def line(self, text: str) -> None:
        """Emit one line of output (without its newline)."""
        if self.to_screen:
            with launch_config._lock:
                sys.stdout.write(self.screen_line(text) + '\n')
                sys.stdout.flush()
        if self.to_log:
            launch_config.file_handler().handle(logging.LogRecord(
                self.process_name, logging.INFO, '', 0, text, None, None))
        if self.own_log:
            for filename in (f'{self.process_name}-{self.stream}.log',
                             f'{self.process_name}-stdout_stderr.log'):
                stream = launch_config.own_log(filename)
                stream.write(text + '\n')
                stream.flush()


_OUTPUT_MODES = {
    #            stdout: (screen, log, own)      stderr: (screen, log, own)
    'screen': ((True, False, False), (True, False, False)),
    'log': ((False, True, False), (True, True, False)),
    'both': ((True, True, False), (True, True, False)),
    'own_log': ((False, False, True), (False, False, True)),
    'full': ((True, True, True), (True, True, True)),
}


def get_output_loggers(process_name: str, output: str, *,
                       screen_line: Callable[[str], str] | None = None,
                       ) -> tuple[_OutputLogger, _OutputLogger]:
    """Return (stdout, stderr) writers for a process's `output` setting.

    'screen' prints both streams; 'log' (the default) writes both to launch.log
    and also prints stderr; 'both' does both; 'own_log' writes per-process
    files only.  OVERRIDE_LAUNCH_PROCESS_OUTPUT (set by `ros2 launch -a`)
    overrides the setting of every process.  `screen_line` formats a line for
    the screen (ExecuteProcess's `output_format`; default `[name] line`); the
    log files keep the bare line under the process's name.
    """
    output = os.environ.get('OVERRIDE_LAUNCH_PROCESS_OUTPUT') or output
    if output not in _OUTPUT_MODES:
        raise ValueError(f"output '{output}' is not one of {sorted(_OUTPUT_MODES)}")
    out_mode, err_mode = _OUTPUT_MODES[output]
    return (_OutputLogger(process_name, 'stdout', *out_mode, screen_line=screen_line),
            _OutputLogger(process_name, 'stderr', *err_mode, screen_line=screen_line))


def reset() -> None:
    """Reset logging so that the next launch gets a fresh log folder."""
    launch_config.reset()
