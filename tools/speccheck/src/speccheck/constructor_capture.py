"""Remember the constructor arguments of launch_ros actions created in a block.

A Node action only works out its name, namespace and parameters when it is
executed, and executing it starts the process; SetParametersFromFile and
SetUseSimTime have no documented getter for what they were given.  Their
constructor arguments (`package=`, `executable=`, `name=`, `namespace=`,
`parameters=`, `remappings=`, `ros_arguments=`; the file name; the value:
the documented public API) are all the static check needs, so while a
launch file is loaded we record them; the objects are created exactly as
usual.  Works with any implementation whose constructors take these
arguments.
"""
from __future__ import annotations

import functools
import inspect
import threading
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from typing import Any

_lock = threading.Lock()


class ConstructorArguments:
    """Constructor arguments (by parameter name) of each recorded object."""

    def __init__(self) -> None:
        self._by_id: dict[int, tuple[Any, dict[str, Any]]] = {}

    def record(self, obj: Any, arguments: dict[str, Any]) -> None:
        self._by_id.setdefault(id(obj), (obj, arguments))  # the outermost class wins

    def get(self, obj: Any) -> dict[str, Any] | None:
        """The arguments `obj` was created with, or None if it was made outside the block."""
        entry = self._by_id.get(id(obj))
        return entry[1] if entry is not None and entry[0] is obj else None


def _named_arguments(signature: inspect.Signature, args: tuple, kwargs: dict) -> dict[str, Any]:
    try:
        bound = signature.bind(*args, **kwargs)
    except TypeError:  # the constructor will raise the real error itself
        return dict(kwargs)
    named: dict[str, Any] = {}
    for name, value in bound.arguments.items():
        kind = signature.parameters[name].kind
        if kind is inspect.Parameter.VAR_KEYWORD:
            named.update(value)
        elif kind is not inspect.Parameter.VAR_POSITIONAL:
            named[name] = value
    named.pop('self', None)
    return named


@contextmanager
def capturing_constructor_arguments(classes: Iterable[type]) -> Iterator[ConstructorArguments]:
    """Within the block, objects of `classes` (and subclasses) record their arguments."""
    recorded = ConstructorArguments()
    with _lock:
        originals = {cls: cls.__dict__['__init__'] for cls in classes
                     if '__init__' in cls.__dict__}
        for cls, original in originals.items():
            cls.__init__ = _recording(original, recorded)
        try:
            yield recorded
        finally:
            for cls, original in originals.items():
                cls.__init__ = original


def _recording(original: Any, recorded: ConstructorArguments) -> Any:
    signature = inspect.signature(original)

    @functools.wraps(original)
    def recording_init(self: Any, *args: Any, **kwargs: Any) -> None:
        recorded.record(self, _named_arguments(signature, (self, *args), kwargs))
        original(self, *args, **kwargs)
    return recording_init
