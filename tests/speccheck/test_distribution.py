"""speccheck is its own distribution (tools/speccheck), with a `speccheck` command
that behaves like `python -m speccheck`."""
from __future__ import annotations

import subprocess
import sys
import tomllib
from importlib import metadata
from pathlib import Path

import speccheck
from speccheck.__main__ import console

from tests.speccheck.conftest import LAUNCH_FILES

ROOT = Path(__file__).parents[2]
SOURCE = ROOT / 'tools' / 'speccheck' / 'src' / 'speccheck'


def test_speccheck_is_installed_from_its_own_distribution():
    assert Path(speccheck.__file__).parent == SOURCE
    scripts = [entry for entry in metadata.distribution('speccheck').entry_points
               if entry.group == 'console_scripts']
    assert [(entry.name, entry.value) for entry in scripts] == [
        ('speccheck', 'speccheck.__main__:console')]
    assert scripts[0].load() is console
    root = tomllib.loads((ROOT / 'pyproject.toml').read_text())
    assert not any(name.startswith('speccheck')
                   for name in root['tool']['setuptools']['packages']['find']['include'])


def test_the_console_command_checks_like_python_m_speccheck(sourced):
    command = Path(sys.executable).parent / 'speccheck'
    words = ['static', str(LAUNCH_FILES / 'scoped.yaml'), str(LAUNCH_FILES / 'scoped.launch.py')]
    as_command = subprocess.run([str(command), *words], env=sourced, capture_output=True,
                                text=True, timeout=120)
    as_module = subprocess.run([sys.executable, '-m', 'speccheck', *words], env=sourced,
                               capture_output=True, text=True, timeout=120)
    assert as_command.returncode == as_module.returncode == 1, as_command.stderr
    assert as_command.stdout == as_module.stdout
    assert 'FAILED      topic /scan: publisher /robot1/lidar' in as_command.stdout
    usage = subprocess.run([str(command), '--help'], capture_output=True, text=True, timeout=60)
    assert usage.returncode == 0 and usage.stdout.startswith('usage: speccheck ')
