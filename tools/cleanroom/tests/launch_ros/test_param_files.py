"""Temporary `launch_params_*` files: content as rcl reads it, and cleanup."""
import os

import yaml
from launch_ros.utilities import param_files


def test_written_file_has_node_key_and_stays():
    """A node's parameter dictionaries go to a file that stays after the launch, as
    observed on Jazzy (`launch_params_*` files are left in the temporary folder)."""
    path = param_files.write_parameters_file(
        '/fleet/member', {'level': 4, 'names': ('a', 'b'), 'flag': 'yes', 'serial': '007'})
    assert os.path.basename(path).startswith('launch_params_')
    with open(path) as handle:
        content = yaml.safe_load(handle)
    assert content == {'/fleet/member': {'ros__parameters': {
        'level': 4, 'names': ['a', 'b'], 'flag': 'yes', 'serial': '007'}}}
    assert path not in param_files.temporary_files()
    param_files.remove_temporary_files()
    assert os.path.exists(path)
    os.unlink(path)


def test_substituted_files_are_removed_per_owner():
    """The files ParameterFile(allow_substs=True) writes are removed at shutdown."""
    path = param_files.write_temporary_file('a: 1\n', owner='owner-a')
    other = param_files.write_temporary_file('b: 2\n', owner='owner-b')
    assert path in param_files.temporary_files('owner-a')
    param_files.remove_temporary_files('owner-a')
    assert not os.path.exists(path)
    assert os.path.exists(other)
    param_files.remove_temporary_files('owner-b')
    assert not os.path.exists(other)
