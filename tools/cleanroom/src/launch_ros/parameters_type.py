"""Type aliases for what `Node(parameters=...)` accepts, as named in Jazzy."""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

ParameterScalarType = str | int | float | bool | bytes
ParameterSequenceType = Sequence[str] | Sequence[int] | Sequence[float] | Sequence[bool]
ParameterValueType = ParameterScalarType | ParameterSequenceType
SomeParameterValue = Any
SomeParameterName = Any
ParametersDict = Mapping[Any, Any]
SomeParameterFile = str | Path | Any
SomeParameters = Sequence[SomeParameterFile | ParametersDict | Any]
EvaluatedParameterValue = ParameterValueType
EvaluatedParameters = Sequence[Path | Mapping[str, EvaluatedParameterValue] | Any]
