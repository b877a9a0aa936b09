"""Predicates on ExecuteProcess actions, for ProcessTargetedEvent."""
import os
from collections.abc import Callable


def matches_pid(*pids: int) -> Callable[[object], bool]:
    """Match processes by pid."""
    return lambda action: getattr(action, 'process_details', None) is not None and \
        action.process_details.get('pid') in pids


def matches_name(*names: str) -> Callable[[object], bool]:
    """Match processes by final name (e.g. 'talker-1')."""
    return lambda action: getattr(action, 'process_details', None) is not None and \
        action.process_details.get('name') in names


def matches_executable(*executables: str) -> Callable[[object], bool]:
    """Match processes by executable (the first command word, or its basename)."""
    def matcher(action: object) -> bool:
        details = getattr(action, 'process_details', None)
        if not details or not details.get('cmd'):
            return False
        first = details['cmd'][0]
        return first in executables or os.path.basename(first) in executables
    return matcher
