"""Perform a list of substitutions and join the results."""
from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..substitution import Substitution

if TYPE_CHECKING:
    from ..launch_context import LaunchContext


def perform_substitutions(context: 'LaunchContext', subs: Iterable[Substitution]) -> str:
    """Return the concatenated text of `subs` performed in `context`."""
    return ''.join(sub.perform(context) for sub in subs)
