"""`post_shutdown_test()`: marks TestCase classes that run after the launch stopped."""
from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

T = TypeVar('T', bound=type)

POST_SHUTDOWN_ATTRIBUTE = '__post_shutdown_test__'


def post_shutdown_test() -> Callable[[T], T]:
    """Decorate a unittest.TestCase class to run it once the processes have shut down."""
    def decorator(test_class: T) -> T:
        setattr(test_class, POST_SHUTDOWN_ATTRIBUTE, True)
        return test_class
    return decorator


def is_post_shutdown(test_class: type) -> bool:
    """True for classes decorated with post_shutdown_test()."""
    return bool(getattr(test_class, POST_SHUTDOWN_ATTRIBUTE, False))
