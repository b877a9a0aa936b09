"""Launch arguments given on the launch_test command line."""
from __future__ import annotations


def parse_launch_arguments(launch_arguments: list[str]) -> list[tuple[str, str]]:
    """'<name>:=<value>' items as (name, value); anything else is an error."""
    parsed = []
    for argument in launch_arguments:
        name, separator, value = argument.partition(':=')
        if not separator or not name:
            from .loader import LaunchTestError
            raise LaunchTestError(
                f"malformed launch argument '{argument}', expected format '<name>:=<value>'")
        parsed.append((name, value))
    return parsed
