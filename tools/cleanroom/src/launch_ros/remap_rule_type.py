"""Type aliases for `Node(remappings=...)`, as named in Jazzy."""
from __future__ import annotations

from collections.abc import Iterable
from typing import Any

SomeRemapRule = tuple[Any, Any]
SomeRemapRules = Iterable[SomeRemapRule]
RemapRule = tuple[str, str]
RemapRules = Iterable[RemapRule]
