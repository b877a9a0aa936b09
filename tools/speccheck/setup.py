"""speccheck's dependencies, with rclhelpers found next to it.

rclhelpers (the rclpy and process helpers the book's tools share) is on no
package index.  Built from this repository (`pip install ./tools/speccheck`),
speccheck depends on the rclhelpers folder beside it, so that one command
installs both; built anywhere else, on a distribution named rclhelpers.
"""
from pathlib import Path

from setuptools import setup

SIBLING = Path(__file__).resolve().parent.parent / 'rclhelpers'
RCLHELPERS = (f'rclhelpers @ {SIBLING.as_uri()}' if (SIBLING / 'pyproject.toml').is_file()
              else 'rclhelpers')

setup(install_requires=['jsonschema', 'pyyaml', RCLHELPERS])
