import launch
import launch_pytest
import pytest
from common import proc
from launch_pytest.tools import process as tools


@pytest.fixture
def speaker():
    return proc('speaker', 'hello', cached_output=True)


@pytest.fixture
def whisperer():
    return proc('whisperer', '--stderr', 'psst', cached_output=True)


@pytest.fixture
def quitter():
    return proc('quitter', '--exit', '4', '--delay', '0.3', cached_output=True)


@launch_pytest.fixture
def launch_description(speaker, whisperer, quitter):
    return launch.LaunchDescription([speaker, whisperer, quitter,
                                     launch_pytest.actions.ReadyToTest()])


@pytest.mark.launch(fixture=launch_description)
async def test_async_tools(speaker, whisperer, quitter, launch_context):
    await tools.wait_for_start(launch_context, speaker, timeout=20)
    assert await tools.wait_for_output(launch_context, speaker, lambda o: 'hello' in o, 20)
    assert await tools.wait_for_stderr(launch_context, whisperer, lambda o: 'psst' in o, 20)
    assert await tools.wait_for_exit(launch_context, quitter, timeout=20) == 4
    await tools.assert_output(launch_context, speaker, lambda o: 'hello' in o)


@pytest.mark.launch(fixture=launch_description)
def test_sync_tools(speaker, whisperer, quitter, launch_context, launch_service):
    assert launch_service.context is launch_context
    tools.wait_for_start_sync(launch_context, speaker, timeout=20)
    assert tools.wait_for_output_sync(launch_context, speaker, lambda o: 'hello' in o, 20)
    assert tools.wait_for_stderr_sync(launch_context, whisperer, lambda o: 'psst' in o, 20)
    assert tools.wait_for_exit_sync(launch_context, quitter, timeout=20) == 4
    tools.assert_stderr_sync(launch_context, whisperer, lambda o: 'psst' in o)


@pytest.mark.launch(fixture=launch_description)
def test_generator(speaker, launch_context):
    assert tools.wait_for_output_sync(launch_context, speaker, lambda o: 'hello' in o, 20)
    assert speaker.return_code is None
    yield
    assert speaker.return_code == 0  # stopped by the shutdown before this part


@pytest.mark.launch(fixture=launch_description, shutdown=True)
def test_after_shutdown(speaker):
    assert speaker.return_code is not None  # the launch stopped it before the test


@pytest.mark.launch(fixture=launch_description)
async def test_output_never_comes(speaker, launch_context):
    assert await tools.wait_for_output(launch_context, speaker, lambda o: 'goodbye' in o, 1)


@pytest.mark.launch(fixture=launch_description)
def test_errors(launch_context):
    raise RuntimeError('broken test')


@pytest.mark.launch(fixture=launch_description)
@pytest.mark.timeout(2, method='signal')
def test_times_out(speaker, launch_context):
    tools.wait_for_output_sync(launch_context, speaker, lambda o: 'never' in o)


def test_plain_test_is_left_alone():
    assert True
