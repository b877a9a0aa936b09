"""Descriptions of ROS parameters: Parameter, ParameterValue, ParameterFile.

Descriptions are made when the launch file is loaded and evaluated when the
node that uses them is executed, so launch arguments given later (or by an
include) are seen.
"""
from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from launch import LaunchContext, Substitution
from launch.substitutions import TextSubstitution
from launch.utilities import ensure_argument_type, normalize_to_list_of_substitutions

from ._support.file_substitutions import expand_file_substitutions
from ._support.launch_cleanup import ensure_cleanup_registered
from ._support.param_files import remove_temporary_file, write_temporary_file
from ._support.parameter_values import coerce_value, homogeneous, plain_python_value
from ._support.substitution_values import evaluate_value, is_substitution_text, perform_text


class ParameterValue:
    """A parameter value with an optional `value_type` (str, int, float, bool, List[...]).

    Python values are checked against `value_type` right away, as Jazzy does
    (golden 28: `ParameterValue('0.5', value_type=float)` is an error);
    substitutions are typed when evaluated.
    """

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        value = _checked_value(value)
        if value_type is not None and not _contains_substitution(value):
            coerce_value(plain_python_value(value), value_type)
        self.__value = value
        self.__value_type = value_type
        self.__evaluated: Any = None

    def __str__(self) -> str:
        # Jazzy shows one substitution as a list of one (and evaluates it as one text)
        shown = [self.__value] if isinstance(self.__value, Substitution) else self.__value
        return (f'launch_ros.description.ParameterValue(value={shown}, '
                f'value_type={self.__value_type})')

    @property
    def value(self) -> Any:
        # One substitution shows as a list of one, as in Jazzy (evaluated alike).
        return [self.__value] if isinstance(self.__value, Substitution) else self.__value

    @property
    def value_type(self) -> Any:
        return self.__value_type

    @property
    def evaluated_value(self) -> Any:
        """The value of the last `evaluate()` (None before)."""
        return self.__evaluated

    def evaluate(self, context: LaunchContext) -> Any:
        self.__evaluated = evaluate_value(context, self.__value, self.__value_type)
        return self.__evaluated


_SCALARS = (str, int, float, bool)


def _checked_value(value: Any) -> Any:
    """A parameter value as Jazzy takes it: a scalar, a substitution, or a list (any
    other sized iterable becomes one: a tuple, a set, a dict's keys, bytes) of
    scalars, substitutions and lists of substitutions.  A list of scalars only must
    be of one type (ints with floats become floats); other values are refused with
    Jazzy's words."""
    if isinstance(value, (Substitution, *_SCALARS)):
        return value
    if value is None or isinstance(value, ParameterValue) or not hasattr(value, '__iter__'):
        raise TypeError('value should be either a scalar, a substitutions, or a mixed list of '
                        f'scalars and substitutions. Got `value={value}` of type '
                        f'`{type(value)}`. ')
    if not isinstance(value, list):
        len(value)  # as in Jazzy: "object of type 'generator' has no len()"
        value = list(value)
    if not all(isinstance(item, (*_SCALARS, Substitution)) or (
            isinstance(item, list) and all(isinstance(i, Substitution) for i in item))
            for item in value):
        raise TypeError('value is a list, and one of the items is not a scalar, a '
                        f"Substitution or a list of substitutions. Got value='{value}'")
    if any(isinstance(item, (Substitution, list)) for item in value):
        return [TextSubstitution(text=item) if isinstance(item, str) else item
                for item in value]
    uniform = homogeneous(value)
    if uniform is None:
        raise TypeError(f"Input value is not an acceptable 'SomeValueType'.Got value='{value}'")
    return uniform


class Parameter:
    """One named parameter; given to a node it becomes `-p name:=value`."""

    def __init__(self, name: Any, value: Any, *, value_type: Any = None) -> None:
        ensure_argument_type(name, (str, Substitution, Iterable), 'name')
        # The name is kept as a list of substitutions (Jazzy's `Parameter.name`).
        self.__name = normalize_to_list_of_substitutions(name)
        # A ParameterValue is no value of a Parameter: Jazzy refuses it (TypeError).
        self.__value = ParameterValue(value, value_type=value_type)

    def __str__(self) -> str:
        return (f'launch_ros.description.Parameter(name={self.__name}, '
                f'value={self.value}, value_type={self.value_type})')

    @property
    def name(self) -> Any:
        return self.__name

    @property
    def value(self) -> Any:
        return self.__value.value

    @property
    def value_type(self) -> Any:
        return self.__value.value_type

    def evaluate(self, context: LaunchContext) -> tuple[str, Any]:
        return perform_text(context, self.__name), self.__value.evaluate(context)


class ParameterFile:
    """A parameter file, optionally with `$(var ...)`-style substitutions inside.

    With `allow_substs` the file is read, its substitutions expanded and the
    result written to a temporary `launch_params_*` file (golden 13); the
    temporary file goes away with `cleanup()` or when the launch ends.
    """

    def __init__(self, param_file: str | Path | Any, *,
                 allow_substs: bool | Any = False) -> None:
        ensure_argument_type(param_file, (str, Substitution, Iterable, os.PathLike, bytes),
                             'param_file', 'ParameterFile()')
        self.__param_file = (param_file if isinstance(param_file, Path)
                             else normalize_to_list_of_substitutions(param_file))
        self.__allow_substs = (allow_substs if isinstance(allow_substs, bool)
                               else normalize_to_list_of_substitutions(allow_substs))
        self.__evaluated: Path | None = None
        self.__created: str | None = None

    @property
    def param_file(self) -> Any:
        return self.__param_file

    @property
    def allow_substs(self) -> Any:
        return self.__allow_substs

    def _source_path(self, context: LaunchContext) -> str:
        if isinstance(self.__param_file, Path):
            return str(self.__param_file)
        return perform_text(context, self.__param_file)

    def _substitutions_allowed(self, context: LaunchContext) -> bool:
        if isinstance(self.__allow_substs, bool):
            return self.__allow_substs
        text = perform_text(context, self.__allow_substs).strip().lower()
        if text in ('true', '1'):
            return True
        if text in ('false', '0'):
            return False
        raise ValueError(f"allow_substs must be 'true' or 'false', got '{text}'")

    def evaluate(self, context: LaunchContext) -> Path:
        """Return the file the node should read (a temporary one if substituted)."""
        source = self._source_path(context)
        if not self._substitutions_allowed(context) or not os.path.isfile(source):
            self.__evaluated = Path(source)
            return self.__evaluated
        with open(source) as handle:
            text = expand_file_substitutions(context, handle.read(), source)
        ensure_cleanup_registered(context)  # removes the file when this launch ends
        self.__created = write_temporary_file(text, owner=id(context))
        self.__evaluated = Path(self.__created)
        return self.__evaluated

    def cleanup(self) -> None:
        """Delete the temporary file made by `evaluate()`, if any."""
        if self.__created is not None:
            remove_temporary_file(self.__created)
            self.__created = None


def _contains_substitution(value: Any) -> bool:
    if isinstance(value, Substitution) or is_substitution_text(value):
        return True
    if isinstance(value, (list, tuple)):
        return any(_contains_substitution(item) for item in value)
    return False


__all__ = ['Parameter', 'ParameterFile', 'ParameterValue']
