"""Expansion of `$(name arg ...)` substitutions inside text files.

Defined in `launch_ros._support.substitution_text`, below the parameter descriptions.
"""
from .._support.substitution_text import (  # noqa: F401 - public home of these names
    Resolver,
    SubstitutionSyntaxError,
    expand_substitutions,
)
