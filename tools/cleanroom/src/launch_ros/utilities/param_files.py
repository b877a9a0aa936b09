"""Temporary parameter files (`launch_params_*`) and their removal.

Defined in `launch_ros._support.param_files`, below the parameter descriptions.
"""
from .._support.param_files import (  # noqa: F401 - public home of these names
    TEMP_PREFIX,
    parameters_document,
    remove_temporary_file,
    remove_temporary_files,
    temporary_files,
    write_parameters_file,
    write_temporary_file,
)
