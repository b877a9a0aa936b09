"""LaunchTestRunner: launch the system under test and run the tests against it.

The launch runs on the main thread (so Ctrl-C reaches it); the active tests
run on a second thread once ReadyToTest was executed, then the launch is shut
down and the post-shutdown tests run.
"""
from __future__ import annotations

import sys
import threading
import unittest
from collections.abc import Sequence

import launch
from launch.actions import RegisterEventHandler
from launch.events.process import ProcessExited, ProcessIO, ProcessStarted

from .actions.ready_to_test import add_ready_callback
from .io_handler import ActiveIoHandler
from .loader import TestRun, bind_test_args
from .proc_info_handler import ActiveProcInfoHandler
from .test_result import FailResult, TestResult
from .util import KeepAliveProc

TIMED_OUT_WAITING = 'Timed out waiting for processes to start up'
STOPPED_EARLY = 'Processes under test stopped before tests completed'


class _Recorder(launch.EventHandler):
    """Feeds process events to proc_info / proc_output (runs on the launch thread)."""

    def __init__(self, proc_info: ActiveProcInfoHandler, proc_output: ActiveIoHandler) -> None:
        super().__init__(matcher=lambda event: isinstance(
            event, (ProcessStarted, ProcessExited, ProcessIO)))
        self._proc_info = proc_info
        self._proc_output = proc_output

    def handle(self, event, context):
        if isinstance(event, ProcessIO):
            self._proc_output.append(event)
        else:
            self._proc_info.append(event)
        return None


class _SingleRun:
    """State shared by the launch thread and the active-test thread of one TestRun."""

    def __init__(self, test_run: TestRun, launch_args: Sequence[str], debug: bool) -> None:
        self.test_run = test_run
        self.ready = threading.Event()
        self.tests_completed = threading.Event()
        self.proc_info = ActiveProcInfoHandler()
        self.proc_output = ActiveIoHandler()
        self.service = launch.LaunchService(argv=list(launch_args), debug=debug)
        self.active_result: unittest.TestResult | None = None

    def description(self) -> tuple[launch.LaunchDescription, dict[str, object]]:
        test_description, extra = self.test_run.generate_description(self.ready.set)
        add_ready_callback(self.service.context, self.ready.set)
        entities = [RegisterEventHandler(_Recorder(self.proc_info, self.proc_output)),
                    test_description]
        if self.test_run.keep_alive:
            entities.append(KeepAliveProc())
        return launch.LaunchDescription(entities), extra

    def run_active_tests(self, args: dict[str, object]) -> None:
        """Thread body: wait for ReadyToTest, run the active tests, stop the launch."""
        try:
            if not self.ready.wait(self.test_run.ready_timeout):
                print(TIMED_OUT_WAITING, flush=True)
                return
            bind_test_args(self.test_run.pre_shutdown_tests, args)
            runner = unittest.TextTestRunner(stream=sys.stderr, verbosity=2,
                                             resultclass=TestResult)
            self.active_result = runner.run(self.test_run.pre_shutdown_tests)
            self.tests_completed.set()
        finally:
            self.service.shutdown()


class LaunchTestRunner:
    """Runs each TestRun: launch, active tests, shutdown, post-shutdown tests."""

    def __init__(self, test_runs: list[TestRun], launch_file_arguments: Sequence[str] = (),
                 debug: bool = False) -> None:
        self._test_runs = test_runs
        self._launch_file_arguments = list(launch_file_arguments)
        self._debug = debug

    def validate(self) -> None:
        """Check the test configuration before anything is launched."""
        for test_run in self._test_runs:
            if not callable(test_run._generate):
                raise TypeError(f'{test_run}: generate_test_description is not callable')

    def run(self) -> dict[TestRun, tuple[unittest.TestResult, unittest.TestResult]]:
        """Return, for each TestRun, (active results, post-shutdown results)."""
        return {test_run: self._run_one(test_run) for test_run in self._test_runs}

    def _run_one(self, test_run: TestRun) -> tuple[unittest.TestResult, unittest.TestResult]:
        run = _SingleRun(test_run, self._launch_file_arguments, self._debug)
        description, extra = run.description()
        args = dict(extra, proc_info=run.proc_info, proc_output=run.proc_output,
                    test_args=dict(test_run.param_args), launch_service=run.service)
        worker = threading.Thread(target=run.run_active_tests, args=(args,),
                                  name='launch_testing-active-tests', daemon=True)
        run.service.include_launch_description(description)
        worker.start()
        run.service.run(shutdown_when_idle=True)
        if not run.tests_completed.is_set():
            print(STOPPED_EARLY, flush=True)
            return FailResult(), FailResult()
        worker.join()
        bind_test_args(test_run.post_shutdown_tests, args)
        runner = unittest.TextTestRunner(stream=sys.stderr, verbosity=2, resultclass=TestResult)
        post_result = runner.run(test_run.post_shutdown_tests)
        return run.active_result, post_result
