"""A launch_pytest test whose launch starts a process: where each line of the launch lands."""
import launch
import launch_pytest
import pytest
from launch.actions import ExecuteProcess


@launch_pytest.fixture
def sleeper():
    return launch.LaunchDescription([
        ExecuteProcess(cmd=['sleep', '30'], name='sleeper'),
        launch_pytest.actions.ReadyToTest()])


@pytest.mark.launch(fixture=sleeper)
def test_runs():
    print('in test')
