"""Exception raised when a substitution cannot be performed."""


class SubstitutionFailure(RuntimeError):
    """A substitution could not produce its text; str() is the message shown to users."""
