import unittest

import launch
import launch_testing.actions
from common import proc


def generate_test_description():
    sleeper = proc('sleeper', 'zzz')
    return launch.LaunchDescription([sleeper, launch_testing.actions.ReadyToTest()]), \
        {'sleeper': sleeper}


class TestSlow(unittest.TestCase):

    def test_waits_long(self, proc_output, sleeper):
        proc_output.assertWaitFor('never', process=sleeper, timeout=120)
