"""Actions of launch_testing."""
from .ready_to_test import ReadyToTest

__all__ = ['ReadyToTest']
