"""Does the sourced workspace have this package and this executable?

Found the way `ros2 run` finds them: the package through the ament index
(AMENT_PREFIX_PATH), the executable as an executable file in
`<prefix>/lib/<package>/`.
"""
from __future__ import annotations

import os
from pathlib import Path

from ament_index_python.packages import PackageNotFoundError, get_package_prefix


def find_executable(package: str, executable: str) -> tuple[bool, str]:
    """(found, evidence): where it is, or what is missing and what there is instead."""
    try:
        prefix = Path(get_package_prefix(package))
    except (PackageNotFoundError, ValueError):
        return False, (f'package {package!r} is not in the sourced workspace '
                       '(is it built, and is install/setup.bash sourced?)')
    folder = prefix / 'lib' / package
    path = folder / executable
    if path.is_file() and os.access(path, os.X_OK):
        return True, f'{package}/{executable} found in {prefix}'
    present = sorted(entry.name for entry in folder.iterdir()
                     if entry.is_file() and os.access(entry, os.X_OK)) if folder.is_dir() else []
    return False, (f'package {package} has no executable {executable!r}; it has: '
                   f'{", ".join(present) or "none"}')
