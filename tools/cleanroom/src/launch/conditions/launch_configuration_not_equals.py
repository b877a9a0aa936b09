"""LaunchConfigurationNotEquals lives with LaunchConfigurationEquals."""
from .launch_configuration_equals import LaunchConfigurationNotEquals

__all__ = ['LaunchConfigurationNotEquals']
