"""A lookup of a process name nothing matches: Jazzy names the processes there are."""
import unittest

import launch
import launch.actions
import launch_testing
import launch_testing.actions
import launch_testing.util.proc_lookup as proc_lookup
import pytest


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=['sleep', '30'], name='talker'),
        launch.actions.ExecuteProcess(cmd=['sleep', '31'], name='listener'),
        launch_testing.actions.ReadyToTest()])


class TestLookup(unittest.TestCase):

    def test_unknown_name(self, proc_info):
        proc_info.assertWaitForStartup(process='talker', timeout=10)
        proc_info.assertWaitForStartup(process='listener', timeout=10)
        proc_lookup.resolveProcesses(proc_info, process='dock')
