"""launch_yaml: the YAML front end of the launch system (`.launch.yaml` files)."""
from . import entity, launch_description_sources, parser
from .entity import Entity
from .parser import Parser

__all__ = ['Entity', 'Parser', 'entity', 'launch_description_sources', 'parser']
