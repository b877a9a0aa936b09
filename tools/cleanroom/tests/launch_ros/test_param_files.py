"""Temporary `launch_params_*` files: content as rcl reads it, and cleanup."""
import os

import yaml
from launch_ros.utilities import param_files


def test_written_file_has_node_key_and_is_removed_per_owner():
    path = param_files.write_parameters_file(
        '/fleet/member', {'level': 4, 'names': ('a', 'b'), 'flag': 'yes', 'serial': '007'},
        owner='owner-a')
    other = param_files.write_parameters_file('/**', {'x': 1}, owner='owner-b')
    assert os.path.basename(path).startswith('launch_params_')
    with open(path) as handle:
        content = yaml.safe_load(handle)
    assert content == {'/fleet/member': {'ros__parameters': {
        'level': 4, 'names': ['a', 'b'], 'flag': 'yes', 'serial': '007'}}}
    assert path in param_files.temporary_files('owner-a')
    param_files.remove_temporary_files('owner-a')
    assert not os.path.exists(path)
    assert os.path.exists(other)
    param_files.remove_temporary_files('owner-b')
    assert not os.path.exists(other)
