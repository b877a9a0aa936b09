"""Type checks for constructor arguments with messages that name the argument."""
import inspect
from collections.abc import Iterable
from typing import Any


def ensure_argument_type(argument: Any, types: type | Iterable[type],
                         argument_name: str, caller: str | None = None) -> None:
    """Raise TypeError unless `argument` is an instance of one of `types`.

    Catching wrong types at construction time points at the launch file line
    that is wrong instead of failing later inside the launch.
    """
    if not isinstance(argument_name, str):
        raise TypeError("argument 'argument_name' must be a str")
    type_list = list(types) if isinstance(types, (list, tuple, set)) else [types]
    for entry in type_list:
        if not inspect.isclass(entry):
            raise TypeError(f"'types' must contain classes, got '{entry!r}'")
    if isinstance(argument, tuple(type_list)):
        return
    # Jazzy's words: the classes as Python prints them, the caller quoted in front.
    where = f"'{caller}' expected" if caller else 'Expected'
    raise TypeError(f"{where} '{argument_name}' to be one of {type_list}, "
                    f"but got '{argument}' of type '{type(argument)}'")
