"""Yielding tests against a module-scoped launch: Jazzy makes each two items."""
import launch
import launch_pytest
import pytest
from common import proc


@launch_pytest.fixture(scope='module')
def system():
    return launch.LaunchDescription([proc('speaker', 'hello'),
                                     launch_pytest.actions.ReadyToTest()])


@pytest.mark.launch(fixture=system, shutdown=True)
def test_a_shutdown():
    assert True


@pytest.mark.launch(fixture=system)
def test_b_both_parts_pass():
    yield
    assert True


@pytest.mark.launch(fixture=system)
def test_c_fails_before():
    raise AssertionError('before the yield')
    yield


@pytest.mark.launch(fixture=system)
async def test_d_fails_after():
    yield
    raise AssertionError('after the yield')


@pytest.mark.launch(fixture=system)
def test_e_plain():
    assert True
