"""Type alias for values that may be text, a substitution or a mix of both."""
import os
from typing import Iterable, Union

from .substitution import Substitution

SomeSubstitutionsType = Union[
    str,
    Substitution,
    Iterable[Union[str, Substitution]],
]

SomeSubstitutionsType_types_tuple = (str, Substitution, os.PathLike, list, tuple)
