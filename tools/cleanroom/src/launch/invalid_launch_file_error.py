"""Error raised when a launch file cannot be loaded."""


class InvalidLaunchFileError(Exception):
    """A launch file could not be loaded with any of the tried loaders."""
