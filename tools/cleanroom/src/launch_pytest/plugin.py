"""pytest plugin of launch_pytest (registered through the pytest11 entry point).

It acts only on tests marked `@pytest.mark.launch(...)`; every other test of a
session is left alone.  As in Jazzy, a test that yields, against a launch
fixture that outlives one test (scope module, class, session), is two items of
the same name: the code before `yield` runs in place while the launch runs, the
code after it among the shutdown tests, once the launch has been shut down
(skipped when the first part failed).
"""
from __future__ import annotations

import inspect

import pytest
from _pytest.fixtures import FixtureManager

from .fixture import fixture_name
from .launch_runner import LaunchRunner, runner_of

MARKER = 'launch'
SKIPPED_SHUTDOWN = 'shutdown test skipped because the test failed before'
#: The first part of a split yielding test -> its generator, once that part passed.
_PENDING: dict[int, object] = {}
#: pytest 8.1 made FixtureManager.getfixturedefs take the node instead of its node id
#: (Ubuntu 24.04, where Jazzy runs, has pytest 7.4.4).
_GETFIXTUREDEFS_TAKES_NODE = 'node' in inspect.signature(FixtureManager.getfixturedefs).parameters


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line(
        'markers',
        'launch(fixture, shutdown=False): run the test while the launch of the given '
        'launch_pytest fixture runs, or after it shut down when shutdown=True')


def _is_marked(obj: object, module: object = None) -> bool:
    marks = list(getattr(obj, 'pytestmark', [])) + list(getattr(module, 'pytestmark', []))
    return any(getattr(mark, 'name', None) == MARKER for mark in marks)


@pytest.hookimpl(tryfirst=True)
def pytest_pycollect_makeitem(collector, name: str, obj: object):
    """Collect generator tests marked launch (pytest refuses plain yield tests)."""
    if not (inspect.isgeneratorfunction(obj) or inspect.isasyncgenfunction(obj)):
        return None
    if not collector.istestfunction(obj, name):
        return None
    if not _is_marked(obj, getattr(collector, 'module', None)):
        return None
    return list(collector._genfunctions(name, obj))


def _is_shutdown_test(item: pytest.Item) -> bool:
    marker = item.get_closest_marker(MARKER)
    return marker is not None and bool(marker.kwargs.get('shutdown', False))


def _launch_fixture_name(item: pytest.Item) -> str:
    marker = item.get_closest_marker(MARKER)
    target = marker.kwargs.get('fixture', marker.args[0] if marker.args else None)
    name = fixture_name(target)
    if name is None:
        raise pytest.UsageError(
            f'{item.nodeid}: @pytest.mark.launch needs fixture=<a launch_pytest.fixture>')
    return name


def pytest_collection_modifyitems(session, config, items) -> None:
    """Set up each marked test's launch fixture; shutdown tests after the others of a module."""
    marked = [item for item in items if item.get_closest_marker(MARKER) is not None]
    if not marked:
        return  # a session without launch tests is left exactly as it was
    for item in marked:
        name = _launch_fixture_name(item)
        if name not in item.fixturenames:
            item.fixturenames.append(name)
    module_order = {}
    for index, item in enumerate(items):
        module_order.setdefault(getattr(item, 'path', None), index)
    order = {id(item): index for index, item in enumerate(items)}
    for item in [item for item in marked if _split(item)]:
        item._launch_pytest_split = True
        twin = pytest.Function.from_parent(
            item.parent, name=item.name, callspec=getattr(item, 'callspec', None),
            callobj=item.obj, fixtureinfo=item._fixtureinfo, originalname=item.originalname)
        twin._launch_pytest_first_part = item
        order[id(twin)] = order[id(item)]
        items.append(twin)
    items.sort(key=lambda item: (module_order[getattr(item, 'path', None)],
                                 _is_shutdown_test(item) or _is_second_part(item),
                                 order[id(item)]))


def _split(item: pytest.Item) -> bool:
    """Whether ``item`` yields against a launch that outlives it: two items, as in Jazzy."""
    function = getattr(item, 'obj', None)
    if _is_shutdown_test(item) or not (inspect.isgeneratorfunction(function)
                                       or inspect.isasyncgenfunction(function)):
        return False
    manager = item.session._fixturemanager
    where = item if _GETFIXTUREDEFS_TAKES_NODE else item.nodeid
    definitions = manager.getfixturedefs(_launch_fixture_name(item), where)
    return bool(definitions) and definitions[-1].scope != 'function'


def _is_second_part(item: pytest.Item) -> bool:
    return getattr(item, '_launch_pytest_first_part', None) is not None


def _runner(request: pytest.FixtureRequest, item: pytest.Item) -> LaunchRunner:
    if item.get_closest_marker(MARKER) is None:
        pytest.fail(f'{item.nodeid}: launch_service and launch_context need '
                    '@pytest.mark.launch(fixture=...)', pytrace=False)
    name = _launch_fixture_name(item)
    runner = runner_of(request.getfixturevalue(name))
    if runner is None:
        pytest.fail(f"{item.nodeid}: fixture '{name}' is not a launch_pytest.fixture",
                    pytrace=False)
    return runner


@pytest.fixture
def launch_service(request: pytest.FixtureRequest):
    """The LaunchService running the test's launch fixture."""
    return _runner(request, request.node).service


@pytest.fixture
def launch_context(request: pytest.FixtureRequest):
    """The LaunchContext of the test's launch."""
    return _runner(request, request.node).context


@pytest.hookimpl(tryfirst=True)
def pytest_pyfunc_call(pyfuncitem: pytest.Function):
    """Run a marked test against its launch: while it runs, or after it stopped."""
    if pyfuncitem.get_closest_marker(MARKER) is None:
        return None
    runner = _runner(pyfuncitem._request, pyfuncitem)
    function = pyfuncitem.obj
    kwargs = {name: pyfuncitem.funcargs[name] for name in pyfuncitem._fixtureinfo.argnames}
    if _is_second_part(pyfuncitem):
        _second_part(runner, pyfuncitem)
        return True
    if not runner.finished.is_set():
        runner.wait_until_ready()
    if _is_shutdown_test(pyfuncitem):
        runner.stop()
    if getattr(pyfuncitem, '_launch_pytest_split', False):
        generator = function(**kwargs)
        _to_yield(runner, generator)
        _PENDING[id(pyfuncitem)] = generator
    elif inspect.iscoroutinefunction(function):
        runner.run_coroutine(function(**kwargs))
    elif inspect.isasyncgenfunction(function) or inspect.isgeneratorfunction(function):
        generator = function(**kwargs)
        _to_yield(runner, generator)
        _after_yield(runner, generator, pyfuncitem)
    else:
        function(**kwargs)
    return True


def _second_part(runner: LaunchRunner, item: pytest.Item) -> None:
    """The code after the yield of a split test, with the launch shut down."""
    generator = _PENDING.pop(id(item._launch_pytest_first_part), None)
    if generator is None:
        pytest.skip(SKIPPED_SHUTDOWN)
    _after_yield(runner, generator, item)


def _to_yield(runner: LaunchRunner, generator) -> None:
    """Run a yielding test (sync or async) up to its yield, with the launch up."""
    if inspect.isasyncgen(generator):
        runner.run_coroutine(generator.__anext__())
    else:
        next(generator)


def _after_yield(runner: LaunchRunner, generator, item: pytest.Item) -> None:
    """Shut the launch down, then run the rest of a yielding test; it may yield once."""
    runner.stop()
    try:
        if inspect.isasyncgen(generator):
            runner.run_coroutine(generator.__anext__())
        else:
            next(generator)
    except (StopIteration, StopAsyncIteration):
        return
    pytest.fail(f'{item.nodeid}: a launch test must yield only once', pytrace=False)
