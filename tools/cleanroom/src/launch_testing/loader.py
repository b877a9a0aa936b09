"""Load a launch test file: its generate_test_description and its TestCase classes."""
from __future__ import annotations

import importlib.util
import inspect
import os
import sys
import unittest
from collections.abc import Callable
from types import ModuleType

import launch

from .decorator import is_post_shutdown
from .markers import has_marker
from .parametrize import parameter_sets
from .ready_to_test_action_timeout import ready_timeout_of


class LaunchTestError(Exception):
    """A launch test file that cannot be run (the message names the file)."""


def load_module(path: str) -> ModuleType:
    """Import the file as a module named after it (e.g. test_x.py -> test_x)."""
    path = os.path.abspath(path)
    if not os.path.isfile(path):
        raise LaunchTestError(f"Test file '{path}' does not exist")
    name = os.path.basename(path)
    name = name[:-3] if name.endswith('.py') else name
    folder = os.path.dirname(path)
    if folder not in sys.path:
        sys.path.insert(0, folder)
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise LaunchTestError(f"Test file '{path}' is not a Python file")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


class TestRun:
    """One launch of the system under test and the tests that run against it."""

    def __init__(self, module: ModuleType, name: str, generate: Callable,
                 param_args: dict[str, object]) -> None:
        self.module = module
        self.name = name
        self._generate = generate
        self.param_args = dict(param_args)
        self.ready_timeout = ready_timeout_of(generate)
        self.keep_alive = has_marker(generate, 'keep_alive')
        loader = unittest.TestLoader()
        classes = [obj for obj in vars(module).values()
                   if isinstance(obj, type) and issubclass(obj, unittest.TestCase)
                   and obj.__module__ == module.__name__]
        self.pre_shutdown_tests = unittest.TestSuite(
            loader.loadTestsFromTestCase(c) for c in classes if not is_post_shutdown(c))
        self.post_shutdown_tests = unittest.TestSuite(
            loader.loadTestsFromTestCase(c) for c in classes if is_post_shutdown(c))

    def __str__(self) -> str:
        return self.name

    def generate_description(self, ready_fn: Callable[[], None]
                             ) -> tuple[launch.LaunchDescription, dict[str, object]]:
        """Call generate_test_description; return (description, values for the tests)."""
        available = dict(self.param_args, ready_fn=ready_fn)
        parameters = inspect.signature(self._generate).parameters
        missing = [p for p in parameters if p not in available
                   and parameters[p].default is inspect.Parameter.empty]
        if missing:
            raise LaunchTestError(
                f"generate_test_description() of '{self.module.__file__}' takes "
                f"{', '.join(missing)}, which no parametrize() gives")
        result = self._generate(**{p: available[p] for p in parameters if p in available})
        extra: dict[str, object] = {}
        if isinstance(result, tuple):
            if len(result) < 1 or not isinstance(result[0], launch.LaunchDescription):
                raise LaunchTestError(self._bad_return(result))
            description = result[0]
            if len(result) > 1:
                if not isinstance(result[1], dict):
                    raise LaunchTestError(self._bad_return(result))
                extra = result[1]
        elif isinstance(result, launch.LaunchDescription):
            description = result
        else:
            raise LaunchTestError(self._bad_return(result))
        return description, dict(self.param_args, **extra)

    def _bad_return(self, result: object) -> str:
        return (f"generate_test_description() of '{self.module.__file__}' must return a "
                'LaunchDescription or a (LaunchDescription, dict) tuple, not '
                f'{type(result).__name__}')


def LoadTestsFromPythonModule(module: ModuleType, *,  # noqa: N802 - Jazzy's name
                              name: str | None = None) -> list[TestRun]:
    """The TestRuns of a module: one, or one per parametrize() value."""
    generate = getattr(module, 'generate_test_description', None)
    if generate is None or not callable(generate):
        raise LaunchTestError(
            f"'{module.__file__}' has no generate_test_description() function")
    base = name or module.__name__
    return [TestRun(module, base + suffix, generate, params)
            for suffix, params in parameter_sets(generate)]


def bind_test_args(suite: unittest.TestSuite, args: dict[str, object]) -> None:
    """Give each test method (and setUp/tearDown) the values its parameters name."""
    for test in _flatten(suite):
        for attribute in (test._testMethodName, 'setUp', 'tearDown'):
            method = getattr(test, attribute, None)
            if method is None:
                continue
            wanted = [p for p in inspect.signature(method).parameters if p in args]
            if not wanted:
                continue
            setattr(test, attribute, _bound(method, {p: args[p] for p in wanted}))
        for key in ('proc_info', 'proc_output', 'test_args'):
            if key in args:
                setattr(test, key, args[key])


def _bound(method: Callable, kwargs: dict[str, object]) -> Callable:
    def call():
        return method(**kwargs)
    call.__name__ = method.__name__
    call.__doc__ = method.__doc__
    return call


def _flatten(suite: unittest.TestSuite) -> list[unittest.TestCase]:
    tests: list[unittest.TestCase] = []
    for item in suite:
        if isinstance(item, unittest.TestSuite):
            tests.extend(_flatten(item))
        else:
            tests.append(item)
    return tests
