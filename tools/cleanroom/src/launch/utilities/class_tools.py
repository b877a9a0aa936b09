"""isinstance/issubclass that also accept classes and instances interchangeably."""
import inspect
from typing import Any


def is_a(obj: Any, entity_type: Any) -> bool:
    """True if `obj` is an instance of `entity_type` (classes are never instances)."""
    return not inspect.isclass(obj) and isinstance(obj, entity_type)


def is_a_subclass(obj: Any, entity_type: Any) -> bool:
    """True if `obj` (a class or an instance) is of or derives from `entity_type`."""
    if inspect.isclass(obj):
        return issubclass(obj, entity_type)
    return isinstance(obj, entity_type)
