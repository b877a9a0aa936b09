import unittest

import launch
import launch.actions
import launch.substitutions
import launch_testing
import launch_testing.actions
from common import proc


@launch_testing.parametrize('word', ['apple', 'pear'])
def generate_test_description(word):
    greeting = launch.substitutions.LaunchConfiguration('greeting')
    speaker = proc('speaker', word, greeting)
    return launch.LaunchDescription([
        launch.actions.DeclareLaunchArgument('greeting', default_value='hi',
                                             description='What the speaker says'),
        speaker, launch_testing.actions.ReadyToTest(),
    ]), {'speaker': speaker}


class TestSpeaker(unittest.TestCase):

    def test_says_word(self, proc_output, speaker, word):
        proc_output.assertWaitFor(word, process=speaker, timeout=20)

    def test_says_greeting(self, proc_output, speaker):
        proc_output.assertWaitFor('howdy', process=speaker, timeout=20)
