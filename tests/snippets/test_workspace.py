"""The snippets workspace installs what setup.py promises, and is rebuilt only
when a snippet changes.  That it builds from scratch with `colcon build` in a
student's terminal is shown by lesson 6.0, which does exactly that (its
`colcon build` cell fails the lesson if any package fails), and by the
book's own workspace build."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from textbook import paths, workspace

PACKAGES = sorted(p.parent for p in paths.SNIPPETS.glob('*/package.xml'))
# What the book's workspace installs: stand-ins for installed real packages are skipped.
BUILT = [p for p in PACKAGES if p.name not in workspace.skipped_packages()]


def test_snippets_hold_packages():
    assert PACKAGES, 'snippets/ must contain at least one package (a folder with package.xml)'


@pytest.mark.parametrize('package', BUILT, ids=lambda p: p.name)
def test_install_has_everything_setup_py_promises(package: Path, ws_install: Path):
    share = ws_install / package.name / 'share' / package.name
    assert (share / 'package.xml').is_file()
    index = ws_install / package.name / 'share/ament_index/resource_index/packages'
    assert (index / package.name).is_file(), 'package not registered in the ament index'
    for folder in ('launch', 'config'):
        for source in sorted((package / folder).glob('*')):
            if source.is_file():
                installed = share / folder / source.name
                assert installed.is_file(), f'{source} is not installed (data_files?)'
                assert installed.read_bytes() == source.read_bytes()


@pytest.fixture
def small_workspace(tmp_path):
    snippets = tmp_path / 'snippets'
    shutil.copytree(PACKAGES[0], snippets / PACKAGES[0].name,
                    ignore=shutil.ignore_patterns('__pycache__'))
    return snippets, tmp_path / 'ws'


def test_rebuilt_only_when_a_snippet_changed(small_workspace):
    snippets, ws = small_workspace
    install = workspace.ensure_built(snippets, ws)
    marker = install / 'built-by-this-run'
    marker.write_text('')

    assert workspace.ensure_built(snippets, ws) == install
    assert marker.exists(), 'an unchanged workspace was rebuilt'

    setup_cfg = next(snippets.glob('*/setup.cfg'))
    setup_cfg.write_text(setup_cfg.read_text() + '\n# changed\n')
    workspace.ensure_built(snippets, ws)
    assert not marker.exists(), 'a changed snippet did not trigger a rebuild'
    assert (install / 'setup.bash').exists()


def test_failed_build_names_the_snippets_and_keeps_the_last_good_install(small_workspace):
    snippets, ws = small_workspace
    install = workspace.ensure_built(snippets, ws)
    good = install.resolve()
    setup_py = next(snippets.glob('*/setup.py'))
    setup_py.write_text("raise SystemExit('broken on purpose')\n")
    with pytest.raises(workspace.WorkspaceBuildError, match='colcon build of .*snippets failed'):
        workspace.ensure_built(snippets, ws)
    assert install.resolve() == good and (install / 'setup.bash').exists()


def test_sourced_env_is_what_setup_bash_gives(ros_env, ws_install):
    for package in BUILT:
        assert str(ws_install / package.name) in ros_env['AMENT_PREFIX_PATH'].split(':')
    assert ros_env['ROS_AUTOMATIC_DISCOVERY_RANGE'] == 'LOCALHOST'
