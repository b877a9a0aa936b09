import unittest

import launch
import launch_testing.actions
import launch_testing.asserts
from common import proc


def generate_test_description():
    talker = proc('talker', 'hello')
    silent = proc('silent')
    quitter = proc('quitter', '--exit', '3', '--delay', '0.5')
    return launch.LaunchDescription([
        talker, silent, quitter, launch_testing.actions.ReadyToTest(),
    ]), {'talker': talker, 'silent': silent, 'quitter': quitter}


class TestActive(unittest.TestCase):

    def test_never_said(self, proc_output, talker):
        proc_output.assertWaitFor('hello', process=talker, timeout=20)  # it has output
        proc_output.assertWaitFor('goodbye', process=talker, timeout=1)

    def test_silent_process(self, proc_output, silent):
        proc_output.assertWaitFor('anything', process=silent, timeout=1)

    def test_raises(self):
        raise RuntimeError('broken test')

    def test_passes(self, proc_info, quitter):
        proc_info.assertWaitForShutdown(process=quitter, timeout=20)


@launch_testing.post_shutdown_test()
class TestExitCodes(unittest.TestCase):

    def test_all_zero(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)

    def test_quitter_three(self, proc_info, quitter):
        launch_testing.asserts.assertExitCodes(proc_info, [3], process=quitter)
