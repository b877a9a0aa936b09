"""Front ends: launch files written in a markup language (XML, YAML).

`Parser` loads a file through the format packages (launch_xml, launch_yaml)
and builds actions with the parse methods registered by `expose_action` /
`expose_substitution`.
"""
from .entity import Entity
from .expose import expose_action, expose_substitution
from .parse_substitution import parse_if_substitutions, parse_substitution
from .parser import InvalidFrontendLaunchFileError, Parser

__all__ = [
    'Entity',
    'InvalidFrontendLaunchFileError',
    'Parser',
    'expose_action',
    'expose_substitution',
    'parse_if_substitutions',
    'parse_substitution',
]
