"""Plain text as a substitution (defined in `launch._text_substitution`, below utilities)."""
from .._text_substitution import TextSubstitution

__all__ = ['TextSubstitution']
