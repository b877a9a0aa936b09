"""Release what launch_ros made for one launch when that launch shuts down.

Defined in `launch_ros._support.launch_cleanup`, below the parameter descriptions.
"""
from .._support.launch_cleanup import (  # noqa: F401 - public home of these names
    add_shutdown_callback,
    ensure_cleanup_registered,
    owner_key,
    run_cleanup,
)
