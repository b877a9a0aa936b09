"""Every installed file comes from one distribution.

When two distributions install the same file (the lock once pinned both
`rclpy` and `ros-rclpy`, issue 13), whichever was installed last wins, so
two students with the same lock could run different code.

Some wheels (the ROS 2 `ros-*` wheels) carry another package's metadata
folder among their files, e.g. ros-rclpy ships `rclpy-7.1.5-py3.11.egg-info`.
importlib.metadata lists that folder as a distribution `rclpy` of its own,
but nobody installs it separately: it is part of the wheel, so its files
count as the wheel's.
"""
from __future__ import annotations

import importlib.metadata as metadata
import os
import sysconfig
from collections import defaultdict
from collections.abc import Iterable
from pathlib import Path

METADATA_SUFFIXES = ('.dist-info', '.egg-info')


def metadata_dir(dist: metadata.Distribution) -> str | None:
    """The distribution's metadata folder (PathDistribution keeps it in `_path`)."""
    path = getattr(dist, '_path', None)
    return os.path.realpath(path) if path is not None else None


def installed_files(dist: metadata.Distribution) -> set[str]:
    """Real paths of the files of `dist` (RECORD), byte code left out."""
    paths = set()
    for file in dist.files or []:
        if '__pycache__' in file.parts or file.suffix == '.pyc':
            continue
        paths.add(os.path.realpath(dist.locate_file(file)))
    return paths


def in_metadata_dir(path: str) -> bool:
    return any(part.endswith(METADATA_SUFFIXES) for part in Path(path).parts)


def shared_files(dists: Iterable[metadata.Distribution]) -> dict[str, list[str]]:
    """Installed paths owned by more than one distribution -> their names.

    Metadata folders are left out, and a distribution whose metadata folder
    is itself among another distribution's files is counted as part of it.
    """
    by_folder: dict[str, tuple[str, set[str]]] = {}
    for dist in dists:
        folder = metadata_dir(dist)
        if folder is not None and folder not in by_folder:  # same folder twice on sys.path
            by_folder[folder] = (dist.metadata['Name'], installed_files(dist))
    shipped = {os.path.dirname(path): folder for folder, (_, files) in by_folder.items()
               for path in files}
    owners: dict[str, set[str]] = defaultdict(set)
    for folder, (name, files) in by_folder.items():
        if shipped.get(folder, folder) != folder:  # inside another distribution's wheel
            continue
        for path in files:
            if not in_metadata_dir(path):
                owners[path].add(f'{name} ({Path(folder).name})')
    return {path: sorted(names) for path, names in owners.items() if len(names) > 1}


def describe(shared: dict[str, list[str]]) -> str:
    return '\n'.join(f'{path}: installed by {" and ".join(names)}'
                     for path, names in sorted(shared.items()))


def environment_distributions() -> Iterable[metadata.Distribution]:
    """The distributions the lock installs: those of this environment's site-packages.

    Not whatever else is on sys.path (a sourced colcon workspace's egg-info
    lists its *sources*, e.g. every ament_python package's setup.py).
    """
    folders = sorted({sysconfig.get_paths()[key] for key in ('purelib', 'platlib')})
    return metadata.distributions(path=folders)


def test_no_file_is_installed_by_two_distributions():
    shared = shared_files(environment_distributions())
    assert not shared, (
        f'{len(shared)} files are installed by more than one distribution; keep one of each '
        f'pair in requirements/base.in and regenerate the lock (make lock):\n'
        f'{describe(shared)}')


def make_distribution(site: Path, folder: str, name: str, files: list[str]) -> None:
    """A minimal installed distribution: METADATA and a RECORD listing `files`."""
    dist_info = site / folder
    dist_info.mkdir(parents=True)
    (dist_info / 'METADATA').write_text(f'Metadata-Version: 2.1\nName: {name}\nVersion: 1.0\n')
    records = files + [f'{folder}/METADATA', f'{folder}/RECORD']
    (dist_info / 'RECORD').write_text(''.join(f'{record},,\n' for record in records))


def test_a_file_of_two_distributions_is_reported_with_both_names(tmp_path):
    make_distribution(tmp_path, 'ros_demo-2.0.dist-info', 'ros-demo',
                      ['demo/__init__.py', 'demo/node.py', 'demo-1.0.egg-info/PKG-INFO',
                       'demo/__pycache__/node.cpython-311.pyc'])
    (tmp_path / 'demo-1.0.egg-info').mkdir()
    (tmp_path / 'demo-1.0.egg-info' / 'PKG-INFO').write_text('Name: demo\nVersion: 1.0\n')
    (tmp_path / 'demo-1.0.egg-info' / 'SOURCES.txt').write_text('demo/__init__.py\n')
    make_distribution(tmp_path, 'demo-1.1.dist-info', 'demo',
                      ['demo/__init__.py', 'demo/__pycache__/node.cpython-311.pyc'])
    make_distribution(tmp_path, 'other-1.0.dist-info', 'other', ['other/__init__.py'])

    shared = shared_files(metadata.distributions(path=[str(tmp_path)]))

    init = os.path.realpath(tmp_path / 'demo' / '__init__.py')
    assert shared == {init: ['demo (demo-1.1.dist-info)', 'ros-demo (ros_demo-2.0.dist-info)']}
    assert f'{init}: installed by demo (demo-1.1.dist-info) and ros-demo' in describe(shared)


def test_metadata_shipped_inside_a_wheel_is_part_of_that_wheel(tmp_path):
    make_distribution(tmp_path, 'ros_demo-2.0.dist-info', 'ros-demo',
                      ['demo/__init__.py', 'demo-1.0.egg-info/PKG-INFO',
                       'demo-1.0.egg-info/SOURCES.txt'])
    (tmp_path / 'demo-1.0.egg-info').mkdir()
    (tmp_path / 'demo-1.0.egg-info' / 'PKG-INFO').write_text('Name: demo\nVersion: 1.0\n')
    (tmp_path / 'demo-1.0.egg-info' / 'SOURCES.txt').write_text('demo/__init__.py\n')

    dists = list(metadata.distributions(path=[str(tmp_path)]))

    assert sorted(d.metadata['Name'] for d in dists) == ['demo', 'ros-demo']
    assert shared_files(dists) == {}
