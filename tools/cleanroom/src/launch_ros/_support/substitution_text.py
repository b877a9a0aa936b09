"""Expansion of `$(name arg ...)` substitutions inside text files.

`ParameterFile(..., allow_substs=True)` lets a YAML file say
`robot_name: $(var robot)`; the launch frontend syntax is used, including
nesting (`$(find-pkg-share $(var pkg))`) and quoted arguments.  This module
only parses; the caller supplies `resolve(name, args) -> str`.
"""
from __future__ import annotations

from collections.abc import Callable

Resolver = Callable[[str, list[str]], str]


class SubstitutionSyntaxError(ValueError):
    """A `$(` without its `)` or an empty substitution name."""


class _Parser:
    def __init__(self, text: str, resolve: Resolver) -> None:
        self.text = text
        self.pos = 0
        self.resolve = resolve

    def error(self, message: str) -> SubstitutionSyntaxError:
        return SubstitutionSyntaxError(f'{message} at offset {self.pos} in {self.text!r}')

    def at_substitution(self) -> bool:
        return self.text.startswith('$(', self.pos)

    def parse_text(self) -> str:
        out: list[str] = []
        while self.pos < len(self.text):
            if self.at_substitution():
                out.append(self.parse_substitution())
            else:
                out.append(self.text[self.pos])
                self.pos += 1
        return ''.join(out)

    def skip_spaces(self) -> None:
        while self.pos < len(self.text) and self.text[self.pos] in ' \t\n':
            self.pos += 1

    def parse_substitution(self) -> str:
        start = self.pos
        self.pos += 2
        name_start = self.pos
        while self.pos < len(self.text) and self.text[self.pos] not in ' \t\n)':
            self.pos += 1
        name = self.text[name_start:self.pos]
        if not name:
            raise self.error('empty substitution name')
        args: list[str] = []
        while True:
            self.skip_spaces()
            if self.pos >= len(self.text):
                self.pos = start
                raise self.error("unterminated '$('")
            if self.text[self.pos] == ')':
                self.pos += 1
                return self.resolve(name, args)
            args.append(self.parse_argument())

    def parse_argument(self) -> str:
        out: list[str] = []
        while self.pos < len(self.text) and self.text[self.pos] not in ' \t\n)':
            char = self.text[self.pos]
            if self.at_substitution():
                out.append(self.parse_substitution())
            elif char in '\'"':
                out.append(self.parse_quoted(char))
            else:
                out.append(char)
                self.pos += 1
        return ''.join(out)

    def parse_quoted(self, quote: str) -> str:
        self.pos += 1
        out: list[str] = []
        while self.pos < len(self.text) and self.text[self.pos] != quote:
            if self.at_substitution():
                out.append(self.parse_substitution())
            else:
                out.append(self.text[self.pos])
                self.pos += 1
        if self.pos >= len(self.text):
            raise self.error('unterminated quote')
        self.pos += 1
        return ''.join(out)


def expand_substitutions(text: str, resolve: Resolver) -> str:
    """Replace every `$(name args...)` in text by `resolve(name, args)`."""
    return _Parser(text, resolve).parse_text()
