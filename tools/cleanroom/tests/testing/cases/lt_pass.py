import unittest

import launch
import launch_testing
import launch_testing.actions
import launch_testing.asserts
import launch_testing.markers
from common import proc


@launch_testing.markers.keep_alive
def generate_test_description():
    printer = proc('printer', 'alpha', 'beta', 'gamma', '--exit', '0')
    shouter = proc('shouter', '--stderr', 'loud')
    return launch.LaunchDescription([
        printer, shouter, launch_testing.actions.ReadyToTest(),
    ]), {'printer': printer, 'shouter': shouter}


class TestWhileRunning(unittest.TestCase):

    def test_waits_for_output(self, proc_output, printer):
        proc_output.assertWaitFor('beta', process=printer, timeout=20, stream='stdout')

    def test_waits_for_stderr_by_name(self, proc_output):
        proc_output.assertWaitFor('loud', process='shouter', timeout=20, stream='stderr')

    def test_printer_exits(self, proc_info, printer):
        proc_info.assertWaitForShutdown(process=printer, timeout=20)


@launch_testing.post_shutdown_test()
class TestAfterShutdown(unittest.TestCase):

    def test_exit_codes(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)

    def test_in_order(self, proc_output, printer):
        launch_testing.asserts.assertInStdout(proc_output, 'gamma', printer)
        with launch_testing.asserts.assertSequentialStdout(proc_output, printer) as cm:
            cm.assertInStdout('alpha')
            cm.assertInStdout('gamma')
