"""labkit.sourced_environment: the environment a student's terminal has after
`source install/setup.bash` (what the exercise checks and lesson 6.13 use)."""
from __future__ import annotations

import labkit


def _workspace(tmp_path, script: str):
    (tmp_path / 'install').mkdir()
    (tmp_path / 'install' / 'setup.bash').write_text(script)
    return tmp_path


def test_what_setup_bash_exports_is_in_the_environment(tmp_path):
    workspace = _workspace(tmp_path, 'export AMENT_PREFIX_PATH="/ws/install:$AMENT_PREFIX_PATH"\n'
                                     'echo noise on stdout\n')
    env = labkit.sourced_environment(workspace, {'AMENT_PREFIX_PATH': '/opt/ros/jazzy',
                                                 'PATH': '/usr/bin:/bin'})
    assert env['AMENT_PREFIX_PATH'] == '/ws/install:/opt/ros/jazzy'
    assert env['PATH'] == '/usr/bin:/bin'
    assert not {'_', 'SHLVL', 'PWD', 'OLDPWD'} & set(env)


def test_a_workspace_not_built_leaves_the_environment_as_it_is(tmp_path):
    base = {'PATH': '/usr/bin:/bin', 'ROS_DOMAIN_ID': '7'}
    assert labkit.sourced_environment(tmp_path, base) == base
