"""Turn text, a substitution or a mix of both into a list of substitutions."""
import os
from typing import Any

from .._text_substitution import TextSubstitution
from ..substitution import Substitution


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """Return `subs` as a list of Substitution; text becomes TextSubstitution.

    Accepts str, os.PathLike, Substitution, or an iterable of those (numbers
    are rejected: launch files must say what text they mean).
    """
    def one(item: Any) -> Substitution:
        if isinstance(item, Substitution):
            return item
        if isinstance(item, str):
            return TextSubstitution(text=item)
        if isinstance(item, os.PathLike):
            return TextSubstitution(text=os.fspath(item))
        raise TypeError(f"Failed to normalize given item of type '{type(item)}', "
                        f"when only 'str' or 'launch.Substitution' were expected.")

    if isinstance(subs, (str, Substitution, os.PathLike)):
        return [one(subs)]
    # Anything else is iterated, as in Jazzy: 1 fails with "'int' object is not iterable".
    return [one(item) for item in subs]
