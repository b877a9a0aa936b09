"""Type alias for values that may be text, a substitution or a mix of both."""
import os
from collections.abc import Iterable

from .substitution import Substitution

SomeSubstitutionsType = str | Substitution | Iterable[str | Substitution]

SomeSubstitutionsType_types_tuple = (str, Substitution, os.PathLike, list, tuple)
