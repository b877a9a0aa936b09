"""The `$(...)` substitutions of `launch` and how their arguments map to constructors."""
from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..substitution import Substitution
from ..substitutions import (
    AllSubstitution,
    AndSubstitution,
    AnonName,
    AnySubstitution,
    Command,
    EnvironmentVariable,
    EqualsSubstitution,
    FileContent,
    FindExecutable,
    IfElseSubstitution,
    LaunchConfiguration,
    NotEqualsSubstitution,
    NotSubstitution,
    OrSubstitution,
    PythonExpression,
    ThisLaunchFile,
    ThisLaunchFileDir,
)
from .expose import register_substitution_parse_method

Arguments = list[list[Substitution]]
Parsed = tuple[type, dict[str, Any]]


def check_count(name: str, args: Arguments, minimum: int, maximum: int) -> None:
    """TypeError naming the substitution when it got too few or too many arguments."""
    if not minimum <= len(args) <= maximum:
        expected = str(minimum) if minimum == maximum else f'{minimum} to {maximum}'
        raise TypeError(f"'{name}' substitution expects {expected} argument(s), "
                        f'got {len(args)}')


def _name_and_default(name: str, cls: type, key: str, default_key: str
                      ) -> Callable[[Arguments], Parsed]:
    def parse(args: Arguments) -> Parsed:
        check_count(name, args, 1, 2)
        kwargs: dict[str, Any] = {key: args[0]}
        if len(args) == 2:
            kwargs[default_key] = args[1]
        return cls, kwargs
    return parse


def _no_arguments(name: str, cls: type) -> Callable[[Arguments], Parsed]:
    def parse(args: Arguments) -> Parsed:
        check_count(name, args, 0, 0)
        return cls, {}
    return parse


def _positional(name: str, cls: type, keys: tuple[str, ...], required: int
                ) -> Callable[[Arguments], Parsed]:
    def parse(args: Arguments) -> Parsed:
        check_count(name, args, required, len(keys))
        return cls, dict(zip(keys[:len(args)], args, strict=True))
    return parse


def _construct_variadic(*, cls: type, args: Arguments) -> Substitution:
    """Constructor adapter for substitutions taking *args (any, all)."""
    return cls(*args)


def _variadic(cls: type) -> Callable[[Arguments], Parsed]:
    def parse(args: Arguments) -> Parsed:
        return _construct_variadic, {'cls': cls, 'args': args}
    return parse


def _optenv(args: Arguments) -> Parsed:
    check_count('optenv', args, 1, 2)
    return EnvironmentVariable, {'name': args[0],
                                 'default_value': args[1] if len(args) == 2 else ''}


def _eval(args: Arguments) -> Parsed:
    check_count('eval', args, 1, 2)
    kwargs: dict[str, Any] = {'expression': args[0]}
    if len(args) == 2:
        kwargs['python_modules'] = [args[1]]
    return PythonExpression, kwargs


def _find_exec(args: Arguments) -> Parsed:
    check_count('find-exec', args, 1, 1)
    return FindExecutable, {'name': args[0]}


PARSE_METHODS: dict[str, Callable[[Arguments], Parsed]] = {
    'var': _name_and_default('var', LaunchConfiguration, 'variable_name', 'default'),
    'env': _name_and_default('env', EnvironmentVariable, 'name', 'default_value'),
    'optenv': _optenv,
    'eval': _eval,
    'dirname': _no_arguments('dirname', ThisLaunchFileDir),
    'filename': _no_arguments('filename', ThisLaunchFile),
    'find-exec': _find_exec,
    'command': _name_and_default('command', Command, 'command', 'on_stderr'),
    'anon': _positional('anon', AnonName, ('name',), 1),
    'file-content': _positional('file-content', FileContent, ('path',), 1),
    'not': _positional('not', NotSubstitution, ('value',), 1),
    'and': _positional('and', AndSubstitution, ('left', 'right'), 2),
    'or': _positional('or', OrSubstitution, ('left', 'right'), 2),
    'any': _variadic(AnySubstitution),
    'all': _variadic(AllSubstitution),
    'equals': _positional('equals', EqualsSubstitution, ('left', 'right'), 2),
    'not-equals': _positional('not-equals', NotEqualsSubstitution, ('left', 'right'), 2),
    'if-else': _positional('if-else', IfElseSubstitution,
                           ('condition', 'if_value', 'else_value'), 1),
}

for _name, _method in PARSE_METHODS.items():
    register_substitution_parse_method(_name, _method)
