"""Split a command line attribute into arguments, as a shell would, keeping `$(...)` whole."""
from __future__ import annotations


def split_command_line(text: str) -> list[str]:
    """Split `text` on unquoted whitespace; quotes outside `$(...)` are removed.

    "echo one 'two three'" -> ['echo', 'one', 'two three']; inside a
    substitution everything (quotes, spaces) is kept for its own parser.
    """
    tokens: list[str] = []
    current: list[str] = []
    has_token = False
    quote = ''
    depth = 0
    i = 0
    while i < len(text):
        char = text[i]
        if depth:
            if text.startswith('$(', i):
                depth += 1
                current.append('$(')
                i += 2
                continue
            depth -= char == ')'
            current.append(char)
        elif text.startswith('$(', i):
            depth = 1
            has_token = True
            current.append('$(')
            i += 2
            continue
        elif quote:
            if char == quote:
                quote = ''
            else:
                current.append(char)
        elif char in '\'"':
            quote = char
            has_token = True
        elif char.isspace():
            if has_token:
                tokens.append(''.join(current))
            current, has_token = [], False
        else:
            current.append(char)
            has_token = True
        i += 1
    if quote:
        raise ValueError(f'No closing quotation in command line: {text}')
    if has_token:
        tokens.append(''.join(current))
    return tokens
