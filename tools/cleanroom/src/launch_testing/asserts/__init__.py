"""Assertions over the output and exit codes of launched processes."""
from .assert_exit_codes import (
    EXIT_FORCED,
    EXIT_OK,
    EXIT_SIGINT,
    EXIT_SIGKILL,
    EXIT_SIGQUIT,
    assertExitCodes,
)
from .assert_output import assertDefaultStream, assertInStderr, assertInStdout, assertInStream
from .assert_sequential_output import SequentialTextChecker, assertSequentialStdout

__all__ = [
    'EXIT_FORCED', 'EXIT_OK', 'EXIT_SIGINT', 'EXIT_SIGKILL', 'EXIT_SIGQUIT',
    'SequentialTextChecker', 'assertDefaultStream', 'assertExitCodes', 'assertInStderr',
    'assertInStdout', 'assertInStream', 'assertSequentialStdout',
]
