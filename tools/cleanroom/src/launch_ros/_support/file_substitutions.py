"""Resolve `$(name args)` found in parameter files against the launch context.

Each name maps to the substitution class the launch frontend uses for it,
so `$(var robot)` fails exactly like `LaunchConfiguration('robot')` does
when the argument is missing.
"""
from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any

from launch import LaunchContext

from .substitution_text import SubstitutionSyntaxError, expand_substitutions


def _launch(name: str) -> Any:
    return getattr(importlib.import_module('launch.substitutions'), name)


def _ros(name: str) -> Any:
    return getattr(importlib.import_module('launch_ros.substitutions'), name)


def _env(args: list[str]) -> Any:
    if len(args) == 2:
        return _launch('EnvironmentVariable')(args[0], default_value=args[1])
    return _launch('EnvironmentVariable')(*args)


def _optenv(args: list[str]) -> Any:
    return _launch('EnvironmentVariable')(args[0], default_value=args[1] if len(args) > 1 else '')


def _var(args: list[str]) -> Any:
    if len(args) == 2:
        return _launch('LaunchConfiguration')(args[0], default=args[1])
    return _launch('LaunchConfiguration')(*args)


_FACTORIES: dict[str, Callable[[list[str]], Any]] = {
    'var': _var,
    'env': _env,
    'optenv': _optenv,
    'find-pkg-share': lambda args: _ros('FindPackageShare')(*args),
    'find-pkg-prefix': lambda args: _ros('FindPackagePrefix')(*args),
    'exec-in-pkg': lambda args: _ros('ExecutableInPackage')(*args),
    'find-exec': lambda args: _launch('FindExecutable')(name=args[0]),
    'dirname': lambda args: _launch('ThisLaunchFileDir')(),
    'filename': lambda args: _launch('ThisLaunchFile')(),
    'eval': lambda args: _launch('PythonExpression')(args),
    'command': lambda args: _launch('Command')(' '.join(args)),
    'anon': lambda args: _launch('AnonName')(*args),
}


def expand_file_substitutions(context: LaunchContext, text: str, path: str) -> str:
    """Expand the substitutions of a file's text; errors name the file."""
    def resolve(name: str, args: list[str]) -> str:
        factory = _FACTORIES.get(name)
        if factory is None:
            raise ValueError(f"unknown substitution '$({name} ...)' in parameter file '{path}'")
        return factory(args).perform(context)

    try:
        return expand_substitutions(text, resolve)
    except SubstitutionSyntaxError as exc:
        raise SubstitutionSyntaxError(f"parameter file '{path}': {exc}") from None
