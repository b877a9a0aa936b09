"""Command-line words -> a launch file path and launch arguments, as `ros2 launch` reads them."""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from ament_index_python.packages import PackageNotFoundError, get_package_share_directory


class TargetError(ValueError):
    """A launch file or argument that cannot be used (the message names it)."""


def split_arguments(words: Sequence[str]) -> tuple[list[str], dict[str, str]]:
    """Separate `name:=value` launch arguments from the other words."""
    others, arguments = [], {}
    for word in words:
        if ':=' in word:
            name, value = word.split(':=', 1)
            if not name:
                raise TargetError(f'launch argument {word!r} has no name before :=')
            arguments[name] = value
        elif arguments:
            raise TargetError(f'{word!r} after launch arguments: put the launch file first')
        else:
            others.append(word)
    return others, arguments


def find_launch_file(package_and_file: Sequence[str] | None,
                     path_words: Sequence[str]) -> Path | None:
    """The launch file named by `--launch PKG FILE` or by a path (None if neither)."""
    if package_and_file and path_words:
        raise TargetError(f'give either --launch PKG FILE or a path, not both '
                          f'(extra: {" ".join(path_words)})')
    if len(path_words) > 1:
        raise TargetError(f'one launch file path expected, got: {" ".join(path_words)}')
    if path_words:
        path = Path(path_words[0])
        if not path.is_file():
            raise TargetError(f'{path}: no such launch file')
        return path
    if package_and_file:
        return installed_launch_file(*package_and_file)
    return None


def installed_launch_file(package: str, file_name: str) -> Path:
    """`FILE` in the share folder of `package`, found the way `ros2 launch PKG FILE` does."""
    try:
        share = Path(get_package_share_directory(package))
    except (PackageNotFoundError, ValueError):
        raise TargetError(f'package {package!r} not found in the sourced workspace') from None
    matches = sorted(share.rglob(file_name))
    if not matches:
        raise TargetError(f'file {file_name!r} was not found in the share directory of '
                          f'package {package!r} [{share}] (is it installed by setup.py?)')
    return matches[0]
