"""Descriptions of what the launch system runs (Jazzy's `launch.descriptions`)."""
from .executable import Executable

__all__ = ['Executable']
