"""Type aliases for what `Node(parameters=...)` accepts, as named in Jazzy."""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any, Union

ParameterScalarType = Union[str, int, float, bool, bytes]
ParameterSequenceType = Union[Sequence[str], Sequence[int], Sequence[float], Sequence[bool]]
ParameterValueType = Union[ParameterScalarType, ParameterSequenceType]
SomeParameterValue = Any
SomeParameterName = Any
ParametersDict = Mapping[Any, Any]
SomeParameterFile = Union[str, Path, Any]
SomeParameters = Sequence[Union[SomeParameterFile, ParametersDict, Any]]
EvaluatedParameterValue = ParameterValueType
EvaluatedParameters = Sequence[Union[Path, Mapping[str, EvaluatedParameterValue], Any]]
