"""`parametrize(names, values)`: one launch test run per parameter set."""
from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TypeVar

F = TypeVar('F', bound=Callable)

_ATTRIBUTE = '__launch_testing_parameters__'


def parametrize(argnames: str, argvalues: Iterable) -> Callable[[F], F]:
    """Decorate generate_test_description to run the whole test once per value.

    `argnames` is a comma separated list of parameter names; with more than one
    name each value is a tuple.  The values reach generate_test_description and
    the test methods by parameter name.
    """
    names = [name.strip() for name in argnames.split(',') if name.strip()]
    if not names:
        raise ValueError('parametrize: no parameter names given')
    sets: list[dict] = []
    for value in argvalues:
        values = (value,) if len(names) == 1 else tuple(value)
        if len(values) != len(names):
            raise ValueError(f'parametrize: {value!r} does not give one value for each of '
                             f'{names}')
        sets.append(dict(zip(names, values, strict=True)))

    def decorator(function: F) -> F:
        setattr(function, _ATTRIBUTE, sets)
        return function
    return decorator


def parameter_sets(function: Callable) -> list[tuple[str, dict]]:
    """(name suffix, parameters) for each run; one unnamed run when not parametrized."""
    sets = getattr(function, _ATTRIBUTE, None)
    if sets is None:
        return [('', {})]
    return [('[' + ', '.join(f'{k}={v!r}' for k, v in params.items()) + ']', params)
            for params in sets]
