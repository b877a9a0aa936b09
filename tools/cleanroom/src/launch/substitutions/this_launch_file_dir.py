"""ThisLaunchFileDir lives with ThisLaunchFile; this module keeps Jazzy's import path."""
from .this_launch_file import ThisLaunchFileDir

__all__ = ['ThisLaunchFileDir']
