"""`@launch_pytest.fixture`: a pytest fixture whose value is the launch to test against."""
from __future__ import annotations

import functools
import inspect
from collections.abc import Callable

import pytest

from .launch_runner import LaunchRunner, description_of, register, unregister


def fixture(*args, **kwargs) -> Callable:
    """Like pytest.fixture; the function returns a LaunchDescription (or a sequence whose
    first item is one), or yields it.  The launch starts when the fixture is set up and
    is shut down (all its processes stopped) when the fixture is torn down.
    """
    if args and callable(args[0]) and len(args) == 1 and not kwargs:
        return _make(args[0])

    def decorator(function: Callable) -> Callable:
        return _make(function, *args, **kwargs)
    return decorator


def _make(function: Callable, *args, **kwargs) -> Callable:
    @functools.wraps(function)
    def launch_fixture(*fargs, **fkwargs):
        produced = function(*fargs, **fkwargs)
        generator = produced if inspect.isgenerator(produced) else None
        value = next(generator) if generator is not None else produced
        runner = LaunchRunner(description_of(value, function))
        register(value, runner)
        try:
            runner.start()
            yield value
        finally:
            unregister(value)
            runner.stop()
            if generator is not None:
                _finish(generator)
    launch_fixture._launch_pytest_fixture = True
    return pytest.fixture(*args, **kwargs)(launch_fixture)


def _finish(generator) -> None:
    try:
        next(generator)
    except StopIteration:
        return
    raise RuntimeError('a launch_pytest fixture must yield only once')


def fixture_name(obj: object) -> str | None:
    """The pytest name of a fixture given to @pytest.mark.launch(fixture=...)."""
    if obj is None:
        return None
    if isinstance(obj, str):
        return obj
    name = getattr(obj, 'name', None)
    return name if isinstance(name, str) else getattr(obj, '__name__', None)
