import unittest

import launch
import launch.actions
import launch_testing
import launch_testing.actions
from common import proc


@launch_testing.ready_to_test_action_timeout(1)
def generate_test_description():
    return launch.LaunchDescription([
        proc('sleeper'),
        launch.actions.TimerAction(period=60.0, actions=[launch_testing.actions.ReadyToTest()]),
    ])


class TestNeverRuns(unittest.TestCase):

    def test_something(self):
        self.fail('must not run')
