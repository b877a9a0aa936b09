"""unittest results that also keep each test's duration (for JUnit XML)."""
from __future__ import annotations

import time
import unittest


class TestResult(unittest.TextTestResult):
    """A TextTestResult recording how long each test case took."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.testCaseTimes: dict[unittest.TestCase, float] = {}
        self.__start = 0.0

    def startTest(self, test: unittest.TestCase) -> None:
        self.__start = time.monotonic()
        super().startTest(test)

    def stopTest(self, test: unittest.TestCase) -> None:
        self.testCaseTimes[test] = time.monotonic() - self.__start
        super().stopTest(test)


class FailResult(unittest.TestResult):
    """The result of tests that could not run (the launch ended or never got ready)."""

    def wasSuccessful(self) -> bool:
        return False
