"""The student's package and the book's solutions declare every package their
launch files start nodes from or find files in, so `colcon build` orders the
build correctly and `rosdep` on a real install knows what to fetch."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from textbook import paths

#: Node(package='x'), FindPackageShare('x'), get_package_share_directory('x'),
#: $(find-pkg-share x), <node pkg="x">, YAML `pkg: x`.
USES = re.compile(r"""package=['"](?P<a>\w+)['"]|FindPackageShare\(['"](?P<b>\w+)['"]\)"""
                  r"""|get_package_share_directory\(['"](?P<c>\w+)['"]\)"""
                  r"""|find-pkg-share (?P<d>\w+)|pkg=['"](?P<e>\w+)['"]|^\s*pkg: (?P<f>\w+)\s*$""",
                  re.MULTILINE)
PACKAGES = {
    'my_ws_exercises': paths.SNIPPETS / 'starters' / 'my_ws_exercises',
    'ch06_solutions': paths.SNIPPETS / 'ch06_solutions',
}


def _used(package: Path) -> dict[str, Path]:
    """package name -> one file that uses it (wrong answers are mistakes on purpose)."""
    used: dict[str, Path] = {}
    for path in sorted(package.rglob('*')):
        if not path.is_file() or 'wrong' in path.relative_to(package).parts \
                or path.suffix not in ('.py', '.xml', '.yaml') or path.name == 'package.xml':
            continue
        for match in USES.finditer(path.read_text()):
            used.setdefault(next(group for group in match.groups() if group), path)
    return used


def _declared(package: Path) -> set[str]:
    root = ET.parse(package / 'package.xml').getroot()
    return {element.text for tag in ('depend', 'exec_depend') for element in root.iter(tag)}


@pytest.mark.parametrize('name', PACKAGES)
def test_every_package_a_launch_file_uses_is_declared(name):
    package = PACKAGES[name]
    used = _used(package)
    assert 'my_robot_pkg' in used, 'the pattern found nothing: it no longer matches the files'
    itself = {name, 'my_ws_exercises'}  # solutions are written for the student's package
    missing = {other: path for other, path in used.items()
               if other not in _declared(package) | itself}
    assert not missing, '\n'.join(
        f'{package / "package.xml"} lacks <exec_depend>{other}</exec_depend> '
        f'({paths.rel(path)} uses it)' for other, path in sorted(missing.items()))
