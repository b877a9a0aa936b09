"""Turn text with `$(name args...)` into a list of Substitution objects.

The grammar is read with lark, as Jazzy does:
an unknown substitution name therefore surfaces as lark's VisitError
("Error trying to process rule "substitution": ...").
"""
from __future__ import annotations

import functools
from typing import Any

from lark import Lark, Token, Transformer

from ..substitution import Substitution
from ..substitutions.text_substitution import TextSubstitution
from .expose import instantiate_substitution

GRAMMAR = r"""
// $(name arg ...) inside text; arguments may be quoted and contain substitutions.
template: fragment*
?fragment: substitution | TEXT

substitution: "$(" IDENTIFIER (_WS argument)* _WS? ")"
argument: arg_part+
?arg_part: substitution | UNQUOTED | single_quoted | double_quoted
single_quoted: "'" (substitution | SQ_TEXT)* "'"
double_quoted: "\"" (substitution | DQ_TEXT)* "\""

IDENTIFIER: /[A-Za-z0-9_\-]+/
TEXT: /([^$]|\$(?!\())+/
UNQUOTED: /([^$\s'"()]|\$(?!\())+/
SQ_TEXT: /([^$']|\$(?!\())+/
DQ_TEXT: /([^$"]|\$(?!\())+/
_WS: /\s+/
"""


@functools.lru_cache(maxsize=1)
def _lark() -> Lark:
    return Lark(GRAMMAR, start='template', parser='earley')


def _join_text(parts: list[Any]) -> list[Substitution]:
    """Flatten parts into substitutions, merging neighbouring text."""
    result: list[Substitution] = []
    for part in parts:
        items = part if isinstance(part, list) else [part]
        for item in items:
            if isinstance(item, Token):
                item = TextSubstitution(text=str(item))
            if (isinstance(item, TextSubstitution) and result
                    and isinstance(result[-1], TextSubstitution)):
                result[-1] = TextSubstitution(text=result[-1].text + item.text)
            else:
                result.append(item)
    return result


class ExtractSubstitution(Transformer):
    """Build substitutions bottom-up from the parse tree."""

    def template(self, fragments: list[Any]) -> list[Substitution]:
        return _join_text(fragments)

    def substitution(self, items: list[Any]) -> Substitution:
        name, *arguments = items
        return instantiate_substitution(str(name), arguments)

    def argument(self, parts: list[Any]) -> list[Substitution]:
        return _join_text(parts)

    def single_quoted(self, parts: list[Any]) -> list[Substitution]:
        return _join_text(parts) or [TextSubstitution(text='')]

    double_quoted = single_quoted


def parse_substitution(string: str) -> list[Substitution]:
    """Parse `string`; plain text gives one TextSubstitution (none for '')."""
    if '$(' not in string:
        return [TextSubstitution(text=string)]  # the common case, without the parser
    tree = _lark().parse(string)
    return ExtractSubstitution().transform(tree)


def parse_if_substitutions(value: Any) -> Any:
    """Parse text (and lists of text) for substitutions; other values pass through."""
    if isinstance(value, str):
        return parse_substitution(value)
    if isinstance(value, list):
        return [parse_if_substitutions(item) for item in value]
    return value


def has_substitutions(substitutions: list[Substitution]) -> bool:
    """True when anything but plain text is in `substitutions`."""
    return any(not isinstance(s, TextSubstitution) for s in substitutions)
