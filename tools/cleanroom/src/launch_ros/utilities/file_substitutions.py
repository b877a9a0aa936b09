"""Resolve `$(name args)` found in parameter files against the launch context.

Defined in `launch_ros._support.file_substitutions`, below the parameter descriptions.
"""
from .._support.file_substitutions import (  # noqa: F401 - public home of these names
    expand_file_substitutions,
)
