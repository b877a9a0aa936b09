"""The exception substitutions raise when they cannot produce a value."""
try:
    from launch.substitutions import SubstitutionFailure
except ImportError:  # pragma: no cover - only while the clean-room core lacks it
    class SubstitutionFailure(RuntimeError):
        """Raised by a substitution that cannot be performed."""

__all__ = ['SubstitutionFailure']
